#pragma once
// Contract: GPU timestamps around named scopes of a command buffer. reset() at the start of recording,
// begin()/end() around each scope (they may nest), results() after the submission has completed.
// Times come from timestampPeriod and the queue's valid bits; on a device without timestamps every
// call is a no-op and results() is empty (supported() says which). On a CPU device each stamp outside a
// render pass is followed by an execution barrier (vk::executionBarrier: lavapipe takes a stamp at its next
// flush), so scopes there time their own work at the cost of a flush per stamp; GPUs record the stamps
// alone. A scope around draws inside a render pass instance, where no barrier may go, begins with
// beginInRendering (lavapipe stamps those in the order of its draws).
#include "hairpipe_volk.h"

#include <cstdint>

#include <string>
#include <vector>

namespace hp::vk {
class Context;

struct ScopeTime {
  std::string name;
  double milliseconds = 0.0;
  int depth = 0;  // nesting level, 0 for top-level scopes
};

class GpuProfiler {
 public:
  GpuProfiler(const Context& ctx, std::uint32_t maxScopes, const std::string& name);
  ~GpuProfiler();
  GpuProfiler(const GpuProfiler&) = delete;
  GpuProfiler& operator=(const GpuProfiler&) = delete;

  bool supported() const { return pool_ != VK_NULL_HANDLE; }
  void reset(VkCommandBuffer cmd);
  void begin(VkCommandBuffer cmd, const std::string& scope);
  void beginInRendering(VkCommandBuffer cmd, const std::string& scope);
  void end(VkCommandBuffer cmd);
  // Blocks until the queries of the last recorded frame are available.
  std::vector<ScopeTime> results() const;

 private:
  struct Scope {
    std::string name;
    std::uint32_t beginQuery;
    std::uint32_t endQuery;
    int depth;
    bool inRendering;
  };
  void open(VkCommandBuffer cmd, const std::string& scope, bool inRendering);
  void stamp(VkCommandBuffer cmd, std::uint32_t query, bool inRendering);
  const Context* ctx_ = nullptr;
  VkDevice device_ = VK_NULL_HANDLE;
  const VolkDeviceTable* fn_ = nullptr;  // the Context's device functions
  bool barrierAfterStamp_ = false;       // a CPU device: see the contract
  VkQueryPool pool_ = VK_NULL_HANDLE;
  std::uint32_t capacity_ = 0;
  std::uint32_t used_ = 0;
  double periodNs_ = 1.0;
  std::uint64_t validMask_ = ~0ull;
  std::vector<Scope> scopes_;
  std::vector<std::size_t> open_;
};

// The median of repeated timings (the benchmarks' and drivers' summary of a run); 0 for none.
double median(std::vector<double> values);
}  // namespace hp::vk
