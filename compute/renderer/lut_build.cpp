#include "compute/renderer/lut_build.h"

#include <pthread.h>

#include <atomic>
#include <cstring>
#include <deque>
#include <exception>

#include "engine/core/error.h"
#include "engine/core/shading/lut_cache.h"

namespace hp {
namespace {
// The process's one worker: builds in the order they were queued, each skipped where its owner let it go
// before its turn. Never destroyed: the detached thread waits on it for the life of the process.
struct LutWorker {
  std::mutex mutex;
  std::condition_variable wake;
  std::deque<std::weak_ptr<LutBuild>> queue;  // under mutex
  bool started = false;                          // under mutex
  std::uint32_t holds = 0;                       // under mutex: LutWorkerHold objects alive (the worker waits)
  std::atomic<std::uint64_t> built{0};
};

LutWorker& lutWorker() {
  static LutWorker* const w = new LutWorker;
  return *w;
}
}  // namespace
}  // namespace hp

// The worker thread's body. C linkage for pthread_create, and static: no global symbol leaves the library.
extern "C" {
static void* runLutWorker(void*) {
  hp::LutWorker& w = hp::lutWorker();
  for (;;) {
    std::shared_ptr<hp::LutBuild> build;
    {
      std::unique_lock<std::mutex> lock(w.mutex);
      w.wake.wait(lock, [&] { return !w.queue.empty() && w.holds == 0; });
      build = w.queue.front().lock();
      w.queue.pop_front();
    }
    if (!build) continue;  // replaced before its turn
    ++w.built;              // before run() signals done: a waiter then sees it counted
    build->run();
  }
}
}

namespace hp {
std::shared_ptr<LutBuild> LutBuild::start(const HairMaterial& material, LutMode mode) {
  auto build = std::make_shared<LutBuild>(material, mode);
  LutWorker& w = lutWorker();
  std::lock_guard<std::mutex> lock(w.mutex);
  if (!w.started) {
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    pthread_attr_setdetachstate(&attr, PTHREAD_CREATE_DETACHED);
    pthread_t thread;
    const int rc = pthread_create(&thread, &attr, runLutWorker, nullptr);
    pthread_attr_destroy(&attr);
    if (rc != 0) throw Error(std::string("material tables: could not start the worker thread: ") + std::strerror(rc));
    w.started = true;
  }
  w.queue.push_back(build);
  w.wake.notify_one();
  return build;
}

std::uint64_t LutBuild::builtCount() { return lutWorker().built.load(); }

LutWorkerHold::LutWorkerHold() {
  LutWorker& w = lutWorker();
  std::lock_guard<std::mutex> lock(w.mutex);
  ++w.holds;
}

LutWorkerHold::~LutWorkerHold() {
  LutWorker& w = lutWorker();
  std::lock_guard<std::mutex> lock(w.mutex);
  --w.holds;
  w.wake.notify_one();
}

void LutBuild::run() noexcept {
  try {
    lut_ = *sharedLut(mode_, material_);
    params_ = *sharedMarschnerParams(mode_, material_);
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
