#include "samples/tools/reference/fibre.h"

#include "engine/error.h"

namespace hp::reference {
FibreModel parseFibreModel(const std::string& name) {
  if (name == "marschner") return FibreModel::Marschner;
  throw Error("unknown fibre model '" + name + "' (expected marschner)");
}
}  // namespace hp::reference
