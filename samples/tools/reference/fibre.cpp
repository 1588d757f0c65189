#include "samples/tools/reference/fibre.h"

#include "engine/core/error.h"

namespace hp::reference {
const char* fibreModelName(FibreModel model) { return model == FibreModel::Physical ? "physical" : "marschner"; }

FibreModel parseFibreModel(const std::string& name) {
  if (name == "physical") return FibreModel::Physical;
  if (name == "marschner") return FibreModel::Marschner;
  throw Error("unknown fibre model '" + name + "' (expected physical or marschner)");
}
}  // namespace hp::reference
