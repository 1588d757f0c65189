// Entry point of the `hairpipe` command line tool: builds the CLI11 app from the registered
// subcommands and maps every failure to a message on stderr and exit code 1.
#include <iostream>

#include "engine/core/error.h"
#include "hairpipe/version.h"
#include "samples/cli/command.h"
#include "samples/tools/interrupt_flag.h"

int main(int argc, char** argv) {
  CLI::App app{"hairpipe: a dynamic strand-hair pipeline on Vulkan"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("hairpipe ") + hairpipe::versionString());
  // Parse errors in the tool's one format (CLI11's own lacks the prefix).
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return std::string("hairpipe: error: ") + e.what() + " (--help lists the options)\n";
  });
  for (const auto& setup : hp::cli::commandRegistry()) setup(app);
  try {
    // SIGINT and SIGTERM ask the command to stop at its next safe point (between frames, tiles, cases): it
    // then fails naming the signal, with every file it wrote complete and no temporary file left.
    hp::InterruptFlag interrupt;
    app.parse(argc, argv);
    hp::throwIfInterrupted("after the command finished: its outputs are complete");
  } catch (const CLI::ParseError& e) {
    // --help and --version print and succeed; every other parse error is a usage error: exit code 1,
    // like every other failure of the tool.
    const int code = app.exit(e);
    return code == 0 ? 0 : 1;
  } catch (const hp::Error& e) {
    std::cerr << "hairpipe: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "hairpipe: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
