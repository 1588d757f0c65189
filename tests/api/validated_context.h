#pragma once
// Contract: the public API tests' device, through the public headers only: a headless Context with the
// validation layer (synchronization validation on; a missing device fails the test, never skips it), and
// the end-of-test check that the device is idle and the layer said nothing.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "hairpipe/hairpipe.h"

namespace hairpipe::test {
inline void createValidatedContext(std::optional<Context>& ctx) {
  HeadlessOptions o;
  o.validation = true;
  Result<Context> c = Context::createHeadless(o);
  ASSERT_TRUE(c.ok()) << c.message();
  ctx.emplace(std::move(c).value());
}

inline void expectIdleAndSilent(const Context& ctx) {
  EXPECT_TRUE(ctx.waitIdle().ok());
  const Result<std::vector<std::string>> messages = ctx.validationMessages();
  ASSERT_TRUE(messages.ok()) << messages.message();
  for (const std::string& m : messages.value()) ADD_FAILURE() << m;
}
}  // namespace hairpipe::test
