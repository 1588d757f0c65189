#pragma once
// Contract: the message of the hp::Error a call throws, or "(accepted)" when it returns: what the tests of
// refused input compare their expected messages against.
#include <string>

#include "engine/core/error.h"

namespace hp::test {
template <class Call>
std::string refusalOf(Call&& call) {
  try {
    call();
  } catch (const hp::Error& e) {
    return e.what();
  }
  return "(accepted)";
}
}  // namespace hp::test
