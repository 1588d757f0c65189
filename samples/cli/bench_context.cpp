#include "samples/cli/bench_context.h"

#include "engine/error.h"

namespace hp::cli {
std::unique_ptr<vk::Context> createBenchContext(const std::string& device, const std::string& command) {
  vk::ContextOptions options;
  options.device = device;
  auto ctx = vk::Context::createHeadless(options);
  if (!ctx->timestampsSupported()) throw Error(command + ": the device has no timestamp queries");
  return ctx;
}
}  // namespace hp::cli
