#pragma once
// Contract: GPU timestamps around named scopes of a command buffer. reset() at the start of recording,
// begin()/end() around each scope (they may nest), results() after the submission has completed.
// Times come from timestampPeriod and the queue's valid bits; on a device without timestamps every
// call is a no-op and results() is empty (supported() says which). lavapipe takes a stamp only at its next
// flush, so a scope there can lose its first dispatch to the scope before: a profiler made with
// StampBarriers::OnCpuDevices (the benchmarks) follows each stamp outside a render pass with an execution
// barrier on CPU devices (vk::executionBarrier), and its scopes then time their own work. The default adds
// none: a frame profiled in a test keeps only its own barriers for synchronization validation to check. A
// scope that begins and ends inside a render pass instance, where no barrier may go, begins with
// beginInRendering (lavapipe may stamp such a scope's draws outside it).
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

enum class StampBarriers { None, OnCpuDevices };

class GpuProfiler {
 public:
  GpuProfiler(const Context& ctx, std::uint32_t maxScopes, const std::string& name,
              StampBarriers barriers = StampBarriers::None);
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
  bool barrierAfterStamp_ = false;       // StampBarriers::OnCpuDevices on a CPU device: see the contract
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
