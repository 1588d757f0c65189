// The `hairpipe` command line: every registered subcommand's options, as main() builds them, fed
// fuzzed argument lists (NUL-separated). Callbacks are parked so nothing runs or writes; what is
// fuzzed is option parsing and the option validators. A parse may only end in CLI11's usage errors
// or hp::Error; anything else escapes and libFuzzer records it.
// Each input gets a fresh app (no state carried between inputs), but only the subcommand that the first
// argument naming one names is set up: building all of them costs ~8 ms an input. CLI11 matches
// subcommands by exact name (the tool sets no prefix or case rules), and the root takes only flags, so
// an input with no argument naming a subcommand can enter none: the parse ends in a usage error whether
// or not the others exist, and none is set up for it. Arguments before that name are the root's, as in
// the tool. A later argument naming another subcommand is parsed as an argument of the first, which the
// real tool refuses too (it takes exactly one subcommand).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "engine/core/error.h"
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

// A subcommand's callback owns (through a shared_ptr) the options its CLI::Options write into, so it
// must outlive the parse: it is moved out into `parked` rather than destroyed. The final callback is a
// protected member of CLI::App; naming it through a derived class gives a pointer to that member.
struct CallbackAccess : CLI::App {
  static constexpr std::function<void()> CLI::App::*kFinal = &CallbackAccess::final_callback_;
};

void parkCallbacks(CLI::App& app, std::vector<std::function<void()>>& parked) {
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    parked.push_back(std::move(sub->*CallbackAccess::kFinal));
    sub->*CallbackAccess::kFinal = nullptr;
    parkCallbacks(*sub, parked);
  }
}
// Subcommand name (and alias) -> the registry entries that add it; found once. A name can take several:
// every `bench` suite registers itself under the `bench` subcommand.
const std::map<std::string, std::vector<std::size_t>>& setupsByName() {
  static const std::map<std::string, std::vector<std::size_t>> index = [] {
    std::map<std::string, std::vector<std::size_t>> names;
    const auto& registry = hp::cli::commandRegistry();
    for (std::size_t i = 0; i < registry.size(); ++i) {
      CLI::App scratch;
      registry[i](scratch);
      for (const CLI::App* sub : scratch.get_subcommands([](CLI::App*) { return true; })) {
        names[sub->get_name()].push_back(i);
        for (const std::string& alias : sub->get_aliases()) names[alias].push_back(i);
      }
    }
    return names;
  }();
  return index;
}

// Sets up the subcommand the first argument naming one names (every entry that adds it), or none.
void setUpCommands(CLI::App& app, const std::vector<std::string>& args) {
  const auto& registry = hp::cli::commandRegistry();
  const auto& index = setupsByName();
  for (std::size_t a = 1; a < args.size(); ++a) {
    const auto named = index.find(args[a]);
    if (named == index.end()) continue;
    for (const std::size_t i : named->second) registry[i](app);
    return;
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::function<void()>> parked;  // declared first: outlives the app that points into them
  CLI::App app{"hairpipe"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "hairpipe");
  std::vector<std::string> args = splitArgs(data, size);
  setUpCommands(app, args);
  parkCallbacks(app, parked);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::Error&) {
  } catch (const hp::Error&) {
  }
  return 0;
}
