#include "tests/support/cli_runner.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>

#include <gtest/gtest.h>
#include <sstream>
#include <stdexcept>

namespace hp::test {
std::string slurp(const std::filesystem::path& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

std::size_t filesIn(const std::filesystem::path& dir) {
  if (!std::filesystem::exists(dir)) return 0;
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

CliProcess::CliProcess(const std::vector<std::string>& args, const std::vector<std::string>& extraEnv) {
  char outTemplate[] = "/tmp/hairpipe-cli-out-XXXXXX";
  char errTemplate[] = "/tmp/hairpipe-cli-err-XXXXXX";
  int outFd = mkstemp(outTemplate);
  int errFd = mkstemp(errTemplate);
  if (outFd < 0 || errFd < 0) throw std::runtime_error("runCli: mkstemp failed");
  outPath_ = outTemplate;
  errPath_ = errTemplate;

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, outFd, 1);
  posix_spawn_file_actions_adddup2(&actions, errFd, 2);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);

  std::vector<std::string> all{HAIRPIPE_CLI_PATH};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env(extraEnv);
  for (char** e = environ; *e; ++e) env.push_back(*e);  // the extra entries first: they win
  std::vector<char*> envp;
  for (auto& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);

  const int rc = posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  close(outFd);
  close(errFd);
  if (rc != 0) {
    pid_ = 0;
    std::remove(outPath_.c_str());
    std::remove(errPath_.c_str());
    throw std::runtime_error("runCli: cannot start " + all[0]);
  }
}

CliProcess::~CliProcess() {
  if (pid_ > 0) {
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
  std::remove(outPath_.c_str());
  std::remove(errPath_.c_str());
}

void CliProcess::signal(int sig) const {
  if (pid_ > 0) kill(pid_, sig);
}

CliResult CliProcess::wait() {
  CliResult result;
  int status = 0;
  waitpid(pid_, &status, 0);
  pid_ = 0;
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.out = slurp(outPath_);
  result.err = slurp(errPath_);
  return result;
}

CliResult runCli(const std::vector<std::string>& args, const std::vector<std::string>& extraEnv) {
  CliProcess process(args, extraEnv);
  return process.wait();
}

Xvfb::Xvfb() {
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("Xvfb: pipe failed");
  // -displayfd: Xvfb picks a free display and writes its number once it accepts connections.
  std::vector<std::string> all{"Xvfb", "-displayfd", std::to_string(fds[1]), "-screen", "0", "640x480x24",
                               "-nolisten", "tcp"};
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  const int rc = posix_spawnp(&pid_, "Xvfb", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(fds[1]);
  if (rc != 0) {
    close(fds[0]);
    pid_ = 0;
    throw std::runtime_error("Xvfb is not installed (the Makefile's PACKAGES install xvfb)");
  }
  pollfd p{fds[0], POLLIN, 0};
  std::string number;
  char c = 0;
  while (poll(&p, 1, 30000) > 0 && read(fds[0], &c, 1) == 1 && c != '\n') number += c;
  close(fds[0]);
  if (number.empty()) throw std::runtime_error("Xvfb did not report a display within 30 s");
  display_ = ":" + number;
}

Xvfb::~Xvfb() {
  if (pid_ > 0) {
    kill(pid_, SIGTERM);
    waitpid(pid_, nullptr, 0);
  }
}

namespace {
// One folder per test process (CTest runs each test in its own process, and several checkouts may run
// their suites at once on one machine): fixed names in /tmp then never collide. Removed at exit.
struct ProcessTempFolder {
  std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("hairpipe-test-" + std::to_string(::getpid()));
  ProcessTempFolder() { std::filesystem::create_directories(path); }
  ~ProcessTempFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};
}  // namespace

std::filesystem::path freshTempPath(const std::string& name) {
  static ProcessTempFolder folder;
  auto path = folder.path / name;
  std::filesystem::remove_all(path);  // a file or a folder this process wrote earlier
  return path;
}

void expectRefused(const std::vector<std::string>& command, const std::vector<RefusedCase>& cases,
                   const std::filesystem::path& output) {
  for (const auto& c : cases) {
    std::vector<std::string> args = command;
    args.insert(args.end(), c.args.begin(), c.args.end());
    std::string shown;
    for (const auto& a : c.args) shown += a + " ";
    const CliResult r = runCli(args);
    EXPECT_EQ(r.exitCode, 1) << shown;
    EXPECT_NE(r.err.find(c.needle), std::string::npos) << shown << ": stderr: " << r.err;
    if (!output.empty()) {
      EXPECT_FALSE(std::filesystem::exists(output)) << shown << ": output written";
    }
  }
}
}  // namespace hp::test
