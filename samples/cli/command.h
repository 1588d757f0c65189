#pragma once
// Contract: each subcommand of the `hairpipe` tool lives in its own samples/cli/cmd_*.cpp and registers
// itself with HP_CLI_COMMAND(setupFunction). The setup function adds a CLI11 subcommand to the app and
// sets its callback. Callbacks throw hp::Error (or CLI11 errors) on failure; main() turns those into a
// message on stderr and exit code 1. No subcommand calls exit() itself.
#include <CLI/CLI.hpp>

#include <functional>
#include <vector>

namespace hp::cli {
using CommandSetup = std::function<void(CLI::App&)>;
std::vector<CommandSetup>& commandRegistry();
struct CommandRegistrar {
  explicit CommandRegistrar(CommandSetup setup) { commandRegistry().push_back(std::move(setup)); }
};
}  // namespace hp::cli

#define HP_CLI_CONCAT2(a, b) a##b
#define HP_CLI_CONCAT(a, b) HP_CLI_CONCAT2(a, b)
#define HP_CLI_COMMAND(fn) \
  static const ::hp::cli::CommandRegistrar HP_CLI_CONCAT(hp_cli_registrar_, __LINE__){fn}
