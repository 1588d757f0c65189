#include "samples/tools/character_clip.h"

#include <cmath>

#include "engine/core/error.h"
#include "engine/core/hair/root_binding.h"
#include "engine/core/hair/skeleton_pose.h"

namespace hp {
CharacterClip characterClip(const HairAsset& asset, const std::string& name) {
  if (!asset.character || !asset.character->skinned())
    throw Error("clip:" + name + ": the model has no skinned character mesh (--mesh with a glTF skin)");
  if (!asset.characterCollides)
    throw Error("clip:" + name + ": the scene's colliders replace the character mesh, so its pose would not be collided with");
  return {asset.character.get(), &findClip(*asset.character, name)};
}

ScalpInput characterScalp(const HairAsset& asset) {
  ScalpInput s;
  s.kind = ScalpInput::Kind::Bones;
  s.skin = boundRootSkin(asset.rootBindings, *asset.character);
  s.boneCount = std::uint32_t(asset.character->skeleton.size());
  return s;
}

std::vector<glm::mat4> characterPose(const CharacterClip& c, double seconds) {
  const double duration = c.clip->duration;
  const double t = duration > 0.0 ? std::fmod(std::max(seconds, 0.0), duration) : 0.0;
  return skinningMatrices(*c.mesh, samplePose(*c.mesh, *c.clip, float(t)));
}

void poseCharacter(SimulatePass& pass, const CharacterClip& c, double seconds, const glm::mat4& head) {
  const std::vector<glm::mat4> skin = characterPose(c, seconds);
  if (c.posesMesh) pass.setCharacterPose(skin);
  if (!c.skinsRoots) return;
  std::vector<glm::mat4> bones;
  for (const glm::mat4& m : skin) bones.push_back(head * m);
  pass.setBones(bones);
}

std::optional<std::string> clipOfAnimate(const std::string& animate) {
  if (animate.rfind("clip:", 0) != 0) return std::nullopt;
  if (animate.size() == 5) throw Error("--animate clip:NAME needs the clip's name");
  return animate.substr(5);
}
}  // namespace hp
