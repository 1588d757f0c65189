#include "compute/renderer/lut_build.h"

#include <pthread.h>

#include <cstring>
#include <exception>

#include "engine/core/error.h"
#include "engine/core/shading/lut_cache.h"

// The thread's entry: runs the build its holder names, then lets the holder (a shared_ptr) go. C linkage for
// pthread_create, and static: no global symbol leaves the library.
extern "C" {
static void* runLutBuild(void* holder) {
  auto* build = static_cast<std::shared_ptr<hp::LutBuild>*>(holder);
  (*build)->run();
  delete build;
  return nullptr;
}
}

namespace hp {

std::shared_ptr<LutBuild> LutBuild::start(const HairMaterial& material, LutMode mode) {
  auto build = std::make_shared<LutBuild>(material, mode);
  auto* holder = new std::shared_ptr<LutBuild>(build);
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setdetachstate(&attr, PTHREAD_CREATE_DETACHED);
  pthread_t thread;
  const int rc = pthread_create(&thread, &attr, runLutBuild, holder);
  pthread_attr_destroy(&attr);
  if (rc != 0) {
    delete holder;
    throw Error(std::string("material tables: could not start a worker thread: ") + std::strerror(rc));
  }
  return build;
}

void LutBuild::run() noexcept {
  try {
    lut_ = *sharedLut(mode_, material_);
    params_ = marschnerGpuParams(lut_);
  } catch (const std::exception& e) {
    error_ = e.what();
  } catch (...) {
    error_ = "material tables: an unknown failure";
  }
  std::lock_guard<std::mutex> lock(mutex_);
  done_ = true;
  finished_.notify_all();
}

bool LutBuild::done() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return done_;
}

void LutBuild::wait() const {
  std::unique_lock<std::mutex> lock(mutex_);
  finished_.wait(lock, [&] { return done_; });
}
}  // namespace hp
