// The `hairpipe` command line: every registered subcommand's options, as main() builds them, fed
// fuzzed argument lists (NUL-separated). Callbacks are cleared so nothing runs or writes; what is
// fuzzed is option parsing and the option validators. A parse may only end in CLI11's usage errors
// or hp::Error; anything else escapes and libFuzzer records it.
#include <cstdint>
#include <string>
#include <vector>

#include "engine/error.h"
#include "samples/cli/command.h"

namespace {
std::vector<std::string> splitArgs(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args{"hairpipe"};
  std::string current;
  for (std::size_t i = 0; i < size && args.size() < 48; ++i) {
    if (data[i] == 0) {
      args.push_back(current);
      current.clear();
    } else if (current.size() < 256) {
      current += static_cast<char>(data[i]);
    }
  }
  if (!current.empty()) args.push_back(current);
  return args;
}

void clearCallbacks(CLI::App& app) {
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    sub->callback(std::function<void()>{});
    clearCallbacks(*sub);
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  CLI::App app{"hairpipe"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "hairpipe");
  for (const auto& setup : hp::cli::commandRegistry()) setup(app);
  clearCallbacks(app);
  std::vector<std::string> args = splitArgs(data, size);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::Error&) {
  } catch (const hp::Error&) {
  }
  return 0;
}
