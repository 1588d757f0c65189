#include "samples/cli/bench_context.h"

#include "engine/error.h"

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
  return benchCommand(app)->add_subcommand(suite, description);
}

std::unique_ptr<vk::Context> createBenchContext(const std::string& device, const std::string& command) {
  vk::ContextOptions options;
  options.device = device;
  auto ctx = vk::Context::createHeadless(options);
  if (!ctx->timestampsSupported()) throw Error(command + ": the device has no timestamp queries");
  return ctx;
}
}  // namespace hp::cli
