#pragma once
// Contract: the device every `hairpipe bench-*` command measures on: headless, no validation (it would
// distort the timings), and refused with hp::Error naming the command when it has no timestamps.
#include <memory>
#include <string>

#include "engine/vk/context.h"

namespace hp::cli {
std::unique_ptr<vk::Context> createBenchContext(const std::string& device, const std::string& command);
}  // namespace hp::cli
