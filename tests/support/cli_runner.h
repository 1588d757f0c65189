#pragma once
// Contract: runs the built `hairpipe` tool with arguments and captures its exit code, stdout and stderr,
// so CLI tests check what a user sees. Arguments are passed without a shell.
#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace hp::test {
struct CliResult {
  int exitCode = -1;
  std::string out;
  std::string err;
};
// `extraEnv`: "NAME=value" entries added to (and overriding) the test's environment.
CliResult runCli(const std::vector<std::string>& args, const std::vector<std::string>& extraEnv = {});

// The tool started in the background (stdin /dev/null, stdout/stderr captured), for tests that act on
// it while it runs (a signal). The destructor kills and reaps a child still running.
class CliProcess {
 public:
  explicit CliProcess(const std::vector<std::string>& args, const std::vector<std::string>& extraEnv = {});
  ~CliProcess();
  CliProcess(const CliProcess&) = delete;
  CliProcess& operator=(const CliProcess&) = delete;
  void signal(int sig) const;
  CliResult wait();

 private:
  pid_t pid_ = 0;
  std::string outPath_, errPath_;
};

// A private X server (Xvfb) for window tests, on a display it picks itself; stopped by the destructor.
// A missing Xvfb throws (a failure, never a skip).
class Xvfb {
 public:
  Xvfb();
  ~Xvfb();
  Xvfb(const Xvfb&) = delete;
  Xvfb& operator=(const Xvfb&) = delete;
  std::string displayEnv() const { return "DISPLAY=" + display_; }

 private:
  pid_t pid_ = 0;
  std::string display_;
};
// The whole file's bytes (empty when it cannot be read).
std::string slurp(const std::filesystem::path& path);
// How many entries a folder holds (0 when it does not exist).
std::size_t filesIn(const std::filesystem::path& dir);
// A path in this test process's own temp folder with nothing at it yet (removed when the process exits).
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
