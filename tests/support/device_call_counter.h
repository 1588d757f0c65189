#pragma once
// Contract: while alive, counts the calls made through a context's device function table, by kind: queue
// submissions and waits (vkQueueSubmit2, vkQueueWaitIdle, vkWaitForFences, vkDeviceWaitIdle), memory
// allocations, pipeline creations (compute and graphics) and descriptor pool creations. hairpipe calls the
// device only through that table, so what a call costs the application's device shows here. One counter
// at a time: the hooks are plain function pointers, so the counts and the original table are static.
#include <cstddef>

#include "engine/vk/context.h"

namespace hp::test {
struct DeviceCalls {
  std::size_t queue = 0;            // submissions and waits
  std::size_t allocations = 0;      // vkAllocateMemory
  std::size_t pipelines = 0;        // pipelines created
  std::size_t descriptorPools = 0;  // vkCreateDescriptorPool
};

class DeviceCallCounter {
 public:
  explicit DeviceCallCounter(const vk::Context& ctx) : table_(const_cast<VolkDeviceTable&>(ctx.fn())), saved_(table_) {
    original() = saved_;
    counts() = {};
    hookQueue();
    table_.vkAllocateMemory = [](VkDevice d, const VkMemoryAllocateInfo* i, const VkAllocationCallbacks* a,
                                 VkDeviceMemory* m) {
      ++counts().allocations;
      return original().vkAllocateMemory(d, i, a, m);
    };
    table_.vkCreateComputePipelines = [](VkDevice d, VkPipelineCache c, uint32_t n, const VkComputePipelineCreateInfo* i,
                                         const VkAllocationCallbacks* a, VkPipeline* p) {
      counts().pipelines += n;
      return original().vkCreateComputePipelines(d, c, n, i, a, p);
    };
    table_.vkCreateGraphicsPipelines = [](VkDevice d, VkPipelineCache c, uint32_t n,
                                          const VkGraphicsPipelineCreateInfo* i, const VkAllocationCallbacks* a,
                                          VkPipeline* p) {
      counts().pipelines += n;
      return original().vkCreateGraphicsPipelines(d, c, n, i, a, p);
    };
    table_.vkCreateDescriptorPool = [](VkDevice d, const VkDescriptorPoolCreateInfo* i, const VkAllocationCallbacks* a,
                                       VkDescriptorPool* p) {
      ++counts().descriptorPools;
      return original().vkCreateDescriptorPool(d, i, a, p);
    };
  }
  ~DeviceCallCounter() { table_ = saved_; }
  DeviceCallCounter(const DeviceCallCounter&) = delete;
  DeviceCallCounter& operator=(const DeviceCallCounter&) = delete;

  static const DeviceCalls& calls() { return counts(); }

 private:
  void hookQueue() {
    table_.vkQueueSubmit2 = [](VkQueue q, uint32_t n, const VkSubmitInfo2* s, VkFence f) {
      ++counts().queue;
      return original().vkQueueSubmit2(q, n, s, f);
    };
    table_.vkQueueWaitIdle = [](VkQueue q) {
      ++counts().queue;
      return original().vkQueueWaitIdle(q);
    };
    table_.vkWaitForFences = [](VkDevice d, uint32_t n, const VkFence* f, VkBool32 all, uint64_t t) {
      ++counts().queue;
      return original().vkWaitForFences(d, n, f, all, t);
    };
    table_.vkDeviceWaitIdle = [](VkDevice d) {
      ++counts().queue;
      return original().vkDeviceWaitIdle(d);
    };
  }
  static DeviceCalls& counts() {
    static DeviceCalls c;
    return c;
  }
  static VolkDeviceTable& original() {
    static VolkDeviceTable t{};
    return t;
  }
  VolkDeviceTable& table_;
  VolkDeviceTable saved_;
};
}  // namespace hp::test
