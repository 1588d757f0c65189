#pragma once
// Contract: runs the built `hairpipe` tool with arguments and captures its exit code, stdout and stderr,
// so CLI tests check what a user sees. Arguments are passed without a shell.
#include <filesystem>
#include <string>
#include <vector>

namespace hp::test {
struct CliResult {
  int exitCode = -1;
  std::string out;
  std::string err;
};
CliResult runCli(const std::vector<std::string>& args);
// A path in the temp directory with nothing at it yet (an earlier run's file is removed).
std::filesystem::path freshTempPath(const std::string& name);

// One refused invocation: the options appended to the command, and text the error must contain.
struct RefusedCase {
  std::vector<std::string> args;
  std::string needle;
};
// Runs `command` + each case's args and expects exit code 1, the needle in stderr and, when `output`
// is given, nothing written there. Records a GoogleTest failure per broken expectation.
void expectRefused(const std::vector<std::string>& command, const std::vector<RefusedCase>& cases,
                   const std::filesystem::path& output = {});
}  // namespace hp::test
