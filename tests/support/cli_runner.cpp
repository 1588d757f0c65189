#include "tests/support/cli_runner.h"

#include <fcntl.h>
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
namespace {
std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}
}  // namespace

CliResult runCli(const std::vector<std::string>& args) {
  char outTemplate[] = "/tmp/hairpipe-cli-out-XXXXXX";
  char errTemplate[] = "/tmp/hairpipe-cli-err-XXXXXX";
  int outFd = mkstemp(outTemplate);
  int errFd = mkstemp(errTemplate);
  if (outFd < 0 || errFd < 0) throw std::runtime_error("runCli: mkstemp failed");

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

  pid_t pid = 0;
  int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(outFd);
  close(errFd);
  CliResult result;
  if (rc == 0) {
    int status = 0;
    waitpid(pid, &status, 0);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  result.out = slurp(outTemplate);
  result.err = slurp(errTemplate);
  std::remove(outTemplate);
  std::remove(errTemplate);
  if (rc != 0) throw std::runtime_error("runCli: cannot start " + all[0]);
  return result;
}

std::filesystem::path freshTempPath(const std::string& name) {
  auto path = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove(path);
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
    if (!output.empty()) EXPECT_FALSE(std::filesystem::exists(output)) << shown << ": output written";
  }
}
}  // namespace hp::test
