#include "samples/cli/command.h"

namespace hp::cli {
std::vector<CommandSetup>& commandRegistry() {
  static std::vector<CommandSetup> registry;
  return registry;
}
}  // namespace hp::cli
