#include "samples/tools/simulation_driver.h"

#include "engine/core/hair/skeleton_pose.h"

#include <algorithm>
#include <string>

#include "engine/vk/barriers.h"
#include "engine/vk/submit.h"
#include "engine/vk/transfer.h"
#include "samples/tools/interrupt_flag.h"

namespace hp {
namespace {
constexpr std::uint32_t kMaxFramesPerSubmit = 256;
constexpr std::uint32_t kFramesPerReportedSubmit = 16;  // progress often enough on a slow device
}

SimulationDriver::SimulationDriver(const vk::Context& ctx, SimulatePass& pass, HeadAnimation animation,
                                   float headRadius, Timing timing)
    : ctx_(ctx), pass_(pass), animation_(animation), headRadius_(headRadius), timing_(timing),
      profiler_(ctx, 2 * kMaxFramesPerSubmit, "simulation frames") {}

HeadMotion SimulationDriver::nextMotion() const {
  const double t0 = time(), t1 = (frame_ + 1) * pass_.params().dt;
  return {headTransformAt(animation_, t0, headRadius_), headTransformAt(animation_, t1, headRadius_), t0,
          headTeleportsBetween(animation_, t0, t1)};
}

void SimulationDriver::poseFor(const HeadMotion& motion) {
  if (!clip_.clip) return;
  posedAt_ = motion.time + pass_.params().dt;
  poseCharacter(pass_, clip_, posedAt_, motion.to);
}

std::vector<glm::vec3> SimulationDriver::characterVertices() const {
  if (!clip_.clip) return {};
  return skinMesh(*clip_.mesh, characterPose(clip_, posedAt_)).positions;
}

HeadMotion SimulationDriver::advance() {
  const HeadMotion motion = nextMotion();
  poseFor(motion);
  ++frame_;
  return motion;
}

void SimulationDriver::runFrames(std::uint32_t count, const std::function<void(std::uint32_t done)>& progress) {
  const std::uint32_t total = count;
  while (count > 0) {
    const std::uint32_t batch = std::min(count, progress ? kFramesPerReportedSubmit : kMaxFramesPerSubmit);
    const bool timed = timing_ == Timing::GpuTimestamps;
    vk::submitAndWait(ctx_, [&](VkCommandBuffer cmd) {
      if (timed) profiler_.reset(cmd);
      for (std::uint32_t i = 0; i < batch; ++i) {
        // Each frame reads and writes what the previous one wrote.
        vk::memoryBarrier(ctx_, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeWrite);
        const HeadMotion motion = nextMotion();
        poseFor(motion);
        pass_.record(cmd, motion, timed ? &profiler_ : nullptr);
        ++frame_;
      }
    }, "simulate frames");
    if (timed)
      for (const auto& scope : profiler_.results())
        (scope.name == "simulate grid" ? gridMs_ : scope.name == "character" ? characterMs_ : frameMs_)
            .push_back(scope.milliseconds);
    count -= batch;
    if (progress) progress(total - count);
    if (count > 0) throwIfInterrupted("after " + std::to_string(total - count) + " of " + std::to_string(total) +
                                      " simulated frames");
  }
}

double SimulationDriver::medianFrameMilliseconds() const { return vk::median(frameMs_); }

double SimulationDriver::medianGridMilliseconds() const { return vk::median(gridMs_); }

double SimulationDriver::medianCharacterMilliseconds() const { return vk::median(characterMs_); }

std::vector<glm::vec4> SimulationDriver::readPositions() const {
  return vk::readback<glm::vec4>(ctx_, pass_.positions(), vk::BufferUse::ComputeWrite,
                                 pass_.positions().size() / sizeof(glm::vec4));
}

std::vector<glm::vec4> SimulationDriver::readPrevious() const {
  return vk::readback<glm::vec4>(ctx_, pass_.previous(), vk::BufferUse::ComputeWrite,
                                 pass_.previous().size() / sizeof(glm::vec4));
}

SimStats SimulationDriver::stats() const { return stats(readPositions(), readPrevious()); }

SimStats SimulationDriver::stats(std::span<const glm::vec4> positions, std::span<const glm::vec4> previous) const {
  const auto& p = pass_.params();
  return computeSimStats(positions, previous, pass_.rest(), pass_.particlesPerGuide(), pass_.colliders(), head(),
                         p.pearlRadius, p.dt / p.substeps);
}

float assetHeadRadius(const HairAsset& asset) {
  float r = 0.0f;
  for (const auto& c : asset.colliders) r = std::max(r, c.radius);
  if (r > 0.0f) return r;
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const auto& p : asset.guides.roots()) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return std::max(0.5f * glm::length(hi - lo), 1e-3f);
}
}  // namespace hp
