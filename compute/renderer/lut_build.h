#pragma once
// Contract: one material's lookup tables (buildLut) and their device parameter block (marschnerGpuParams:
// the sky albedo's furnace quadrature, 12-28 ms of CPU) built on a detached POSIX thread, so a material
// change in the frame loop costs the application's thread no table building (HairInstance::setMaterial). The
// build owns copies of its inputs and is shared between the thread and its owner: dropping the owner's
// handle lets the thread finish into nothing. A POSIX thread rather than std::thread: the library never
// references std::terminate (tests/support: Library.NeverCallsAbortOrExit).
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>

#include "engine/core/shading/lut.h"
#include "engine/core/shading/marschner_gpu.h"
#include "engine/core/shading/material.h"

namespace hp {
class LutBuild {
 public:
  // Starts the thread; hp::Error when it cannot be started.
  static std::shared_ptr<LutBuild> start(const HairMaterial& material, LutMode mode);
  LutBuild(const HairMaterial& material, LutMode mode) : material_(material), mode_(mode) {}

  bool done() const;
  void wait() const;  // until done()
  // After done(): the tables, or (error() non-empty) why there are none.
  const MarschnerLut& lut() const { return lut_; }
  const gpu::MarschnerParams& params() const { return params_; }
  const std::string& error() const { return error_; }
  const HairMaterial& material() const { return material_; }
  LutMode mode() const { return mode_; }

  void run() noexcept;  // the thread's body

 private:
  HairMaterial material_;
  LutMode mode_;
  MarschnerLut lut_;
  gpu::MarschnerParams params_{};
  std::string error_;
  mutable std::mutex mutex_;
  mutable std::condition_variable finished_;
  bool done_ = false;  // under mutex_
};
}  // namespace hp
