#pragma once
// Contract: one material's lookup tables (buildLut) and their device parameter block (marschnerGpuParams:
// the sky albedo's furnace quadrature, 12-28 ms of CPU) built off the application's thread, so a material
// change in the frame loop costs it no table building (HairInstance::setMaterial). Builds queue in order for
// the process's one worker (a detached POSIX thread, started with the first build and kept): the queue holds
// each build weakly, so one whose owner let it go before it started (a later setMaterial replaced it) is
// skipped, never built; one already running finishes into nothing. A POSIX thread rather than std::thread:
// the library never references std::terminate (tests/support: Library.NeverCallsAbortOrExit).
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>

#include "engine/core/shading/lut.h"
#include "engine/core/shading/marschner_gpu.h"
#include "engine/core/shading/material.h"

namespace hp {
class LutBuild {
 public:
  // Queues the build (starting the worker if it is not running); hp::Error when the worker cannot be started.
  static std::shared_ptr<LutBuild> start(const HairMaterial& material, LutMode mode);
  // Builds the worker has started in this process (skipped ones not counted); counted before the build is
  // done, so a wait() that returned sees its own build counted.
  static std::uint64_t builtCount();
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

// While one lives the worker starts no build (the one it runs goes on): tests queue several changes and
// release them at once, so which are skipped does not depend on the threads' timing.
class LutWorkerHold {
 public:
  LutWorkerHold();
  ~LutWorkerHold();
  LutWorkerHold(const LutWorkerHold&) = delete;
  LutWorkerHold& operator=(const LutWorkerHold&) = delete;
};
}  // namespace hp
