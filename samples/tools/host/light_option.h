#pragma once
// Contract: one light written as a command-line value (`hairpipe render --light SPEC`, repeatable), read into
// a validated hp::LightSpec. SPEC is a type, then colon-separated KEY=VALUE pairs in any order:
//   directional[:dir=X,Y,Z]                          direction toward the light (normalised; default the sun's)
//   spot:pos=X,Y,Z[:target=X,Y,Z][:cone=DEG][:range=R]  aimed at target (default: `defaultTarget`), cone
//                                                    half-angle in (0, 80] (default 30), inverse-square range >= 0
//   point:pos=X,Y,Z[:range=R]                        shines every way from pos
// and for every type color=R,G,B (each >= 0), intensity=I (>= 0), shadows=on|off (default on). Unknown,
// repeated or missing keys, keys of another type and bad numbers (not a number, NaN, infinite, out of range)
// throw hp::Error naming the key and the value, e.g. "cone=90: must be in (0, 80] degrees". Host-only.
#include <string_view>

#include "engine/core/hair/scene.h"

namespace hp {
LightSpec parseLightOption(std::string_view spec, const glm::vec3& defaultTarget);
// The syntax above in one line per type, for help texts.
const char* lightOptionSyntax();
}  // namespace hp
