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
}  // namespace hp::test
