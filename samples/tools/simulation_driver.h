#pragma once
// Contract: drives a SimulatePass through scripted frames outside an application's frame loop (CLI,
// tests, benchmarks): records a batch of frames into one submission with the frame-to-frame barrier,
// times each frame with GPU timestamps, and reads the state back on request. The head follows a
// HeadAnimation; a jump in it is handed to the pass as a teleport. Timing can be turned off: long runs
// under the validation layer (1.3.239) would otherwise grow its memory with every query-pool reset.
#include <functional>
#include <vector>

#include "compute/strands/simulate_pass.h"
#include "samples/tools/character_clip.h"
#include "samples/tools/host/head_animation.h"
#include "samples/tools/host/sim_stats.h"
#include "engine/vk/profiler.h"

namespace hp {
class SimulationDriver {
 public:
  enum class Timing { GpuTimestamps, None };
  SimulationDriver(const vk::Context& ctx, SimulatePass& pass, HeadAnimation animation, float headRadius,
                   Timing timing = Timing::GpuTimestamps);

  // A skinned character's clip poses the character (and the roots, with Bones input) at each frame's end.
  void setCharacterClip(const CharacterClip& clip) { clip_ = clip; }
  // Simulates `count` frames in submissions of up to 256 frames and waits for them. Appends each
  // frame's GPU ms. With `progress`, submissions are smaller and it is told the frames done after each.
  void runFrames(std::uint32_t count, const std::function<void(std::uint32_t done)>& progress = {});
  const std::vector<double>& frameMilliseconds() const { return frameMs_; }
  // Forgets the recorded frame times (long runs keep their memory flat).
  void clearFrameTimes() {
    frameMs_ = {};
    gridMs_ = {};
    characterMs_ = {};
  }
  // The simulation pass's GPU ms per frame, and the hair grid's (built before it when it acts; 0 when it never did).
  double medianFrameMilliseconds() const;
  double medianGridMilliseconds() const;
  double medianCharacterMilliseconds() const;  // the character's skinning and grid (0 when it never ran)
  // The character's vertices as the last simulated frame posed them (rest without a clip; empty without a character).
  std::vector<glm::vec3> characterVertices() const;

  std::uint32_t frame() const { return frame_; }
  double time() const { return frame_ * pass_.params().dt; }
  glm::mat4 head() const { return headTransformAt(animation_, time(), headRadius_); }
  // The motion of the next frame (what runFrames records for it).
  HeadMotion nextMotion() const;
  // The next frame's motion, counted as simulated: for frames recorded elsewhere (a full render frame).
  HeadMotion advance();

  std::vector<glm::vec4> readPositions() const;
  std::vector<glm::vec4> readPrevious() const;
  SimStats stats() const;
  // The same from a state already read back.
  SimStats stats(std::span<const glm::vec4> positions, std::span<const glm::vec4> previous) const;

 private:
  const vk::Context& ctx_;
  SimulatePass& pass_;
  HeadAnimation animation_;
  float headRadius_;
  Timing timing_;
  std::uint32_t frame_ = 0;
  vk::GpuProfiler profiler_;
  std::vector<double> frameMs_;
  std::vector<double> gridMs_;
  std::vector<double> characterMs_;
  CharacterClip clip_;
  double posedAt_ = 0.0;  // the clip time of the last pose
  // The clip's pose for the frame `motion` simulates (at its end), when there is a clip.
  void poseFor(const HeadMotion& motion);
};

// A head radius for animations and tolerances: the largest collider's, else the roots' extent.
float assetHeadRadius(const HairAsset& asset);
}  // namespace hp
