#pragma once
// Contract: hp::Error is the one exception type hairpipe throws. Its message names what failed
// (a Vulkan call and its VkResult, a file and the problem in it, a parameter and its bad value).
// hairpipe never calls abort() or exit(); the CLI turns an hp::Error into a message and exit code 1.
#include <stdexcept>
#include <string>

namespace hp {
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
}  // namespace hp
