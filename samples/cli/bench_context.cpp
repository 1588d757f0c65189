#include "samples/cli/bench_context.h"

#include "engine/core/error.h"

namespace hp::cli {
CLI::App* benchCommand(CLI::App& app) {
  try {
    return app.get_subcommand("bench");
  } catch (const CLI::OptionNotFound&) {  // the first command to register adds it
    return app.add_subcommand(
        "bench", "Time the whole frame per pass on the device (default head), or one suite: bench SUITE --help");
  }
}

CLI::App* benchSuite(CLI::App& app, const std::string& suite, const std::string& description) {
  CLI::App* bench = benchCommand(app);
  CLI::App* cmd = bench->add_subcommand(suite, description);
  // `bench --strands 10 sim` gives --strands to the frame bench, which does not run when a suite does:
  // refused before the suite runs instead of silently measuring something else.
  cmd->parse_complete_callback([bench, suite] {
    for (const CLI::Option* option : bench->get_options()) {
      if (option->count() == 0 || option == bench->get_help_ptr()) continue;
      throw Error("bench " + suite + ": " + option->get_name() +
                  " before the suite name is an option of the whole-frame bench, not of this suite; put the "
                  "suite's options after '" + suite + "' (see bench " + suite + " --help)");
    }
  });
  return cmd;
}

std::unique_ptr<vk::Context> createBenchContext(const std::string& device, const std::string& command) {
  vk::ContextOptions options;
  options.device = device;
  auto ctx = vk::Context::createHeadless(options);
  if (!ctx->timestampsSupported()) throw Error(command + ": the device has no timestamp queries");
  return ctx;
}
}  // namespace hp::cli
