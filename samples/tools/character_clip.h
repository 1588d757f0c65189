#pragma once
// Contract: an animation clip of an asset's skinned character driving a simulation outside a frame loop (CLI,
// tests): per frame the mesh's pose at the frame's end (the clip looped) goes to the pass's character (its
// collision grid, rebuilt on the device, and the drawn head) and, with Bones scalp input (characterScalp), the
// roots' bone matrices (head to world times the pose). "clip:NAME" on the command line names one.
#include <glm/glm.hpp>

#include <optional>
#include <string>

#include "compute/strands/scalp_input.h"
#include "compute/strands/simulate_pass.h"
#include "engine/core/hair/hair_asset.h"

namespace hp {
struct CharacterClip {
  const CharacterMesh* mesh = nullptr;
  const AnimationClip* clip = nullptr;
  bool skinsRoots = true;  // the pass was made with characterScalp: the roots follow the bones too
  bool posesMesh = true;   // the collision grid (and the drawn head) follow the pose; false keeps the rest pose's
};

// The clip called `name` of the asset's skinned character the hair collides with; throws hp::Error naming
// what is missing (no character, a rigid one, scene colliders in its place, no such clip).
CharacterClip characterClip(const HairAsset& asset, const std::string& name);
// Bones scalp input from the asset's root binding (boundRootSkin): each root follows its triangle's joints.
ScalpInput characterScalp(const HairAsset& asset);
// The clip's skinning matrices at `seconds` (looped).
std::vector<glm::mat4> characterPose(const CharacterClip& clip, double seconds);
// The clip's pose at `seconds` (looped) into the pass: the character's, and the roots' bones placed by `head`.
void poseCharacter(SimulatePass& pass, const CharacterClip& clip, double seconds, const glm::mat4& head);
// "clip:NAME" -> NAME; anything else -> none.
std::optional<std::string> clipOfAnimate(const std::string& animate);
}  // namespace hp
