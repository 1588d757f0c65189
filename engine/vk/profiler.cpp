#include "engine/vk/profiler.h"

#include <algorithm>

#include "engine/core/error.h"
#include "engine/vk/barriers.h"
#include "engine/vk/check.h"
#include "engine/vk/context.h"

namespace hp::vk {
GpuProfiler::GpuProfiler(const Context& ctx, std::uint32_t maxScopes, const std::string& name,
                         StampBarriers barriers)
    : ctx_(&ctx),
      device_(ctx.device()),
      fn_(&ctx.fn()),
      barrierAfterStamp_(barriers == StampBarriers::OnCpuDevices &&
                         ctx.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU),
      capacity_(maxScopes * 2) {
  if (!ctx.timestampsSupported()) return;
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice(), &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice(), &count, families.data());
  std::uint32_t bits = families[ctx.queueFamily()].timestampValidBits;
  validMask_ = bits >= 64 ? ~0ull : ((1ull << bits) - 1);
  periodNs_ = ctx.properties().limits.timestampPeriod;
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = capacity_;
  HP_VK_CHECK(fn_->vkCreateQueryPool(device_, &info, nullptr, &pool_));
  ctx.setName(VK_OBJECT_TYPE_QUERY_POOL, reinterpret_cast<std::uint64_t>(pool_), name);
}

GpuProfiler::~GpuProfiler() {
  if (pool_) fn_->vkDestroyQueryPool(device_, pool_, nullptr);
}

void GpuProfiler::reset(VkCommandBuffer cmd) {
  scopes_.clear();
  open_.clear();
  used_ = 0;
  if (pool_) fn_->vkCmdResetQueryPool(cmd, pool_, 0, capacity_);
}

void GpuProfiler::begin(VkCommandBuffer cmd, const std::string& scope) { open(cmd, scope, false); }

void GpuProfiler::beginInRendering(VkCommandBuffer cmd, const std::string& scope) { open(cmd, scope, true); }

void GpuProfiler::open(VkCommandBuffer cmd, const std::string& scope, bool inRendering) {
  if (!pool_) return;
  if (used_ + 2 > capacity_) throw Error("GpuProfiler: more than " + std::to_string(capacity_ / 2) + " scopes");
  scopes_.push_back({scope, used_, used_ + 1, static_cast<int>(open_.size()), inRendering});
  open_.push_back(scopes_.size() - 1);
  used_ += 2;
  stamp(cmd, scopes_.back().beginQuery, inRendering);
}

// ALL_COMMANDS: the stamp is taken once all earlier work has finished, so a scope measures its own work.
void GpuProfiler::stamp(VkCommandBuffer cmd, std::uint32_t query, bool inRendering) {
  fn_->vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, query);
  if (barrierAfterStamp_ && !inRendering) executionBarrier(*ctx_, cmd);
}

void GpuProfiler::end(VkCommandBuffer cmd) {
  if (!pool_) return;
  if (open_.empty()) throw Error("GpuProfiler::end without a matching begin");
  const Scope& s = scopes_[open_.back()];
  open_.pop_back();
  stamp(cmd, s.endQuery, s.inRendering);
}

std::vector<ScopeTime> GpuProfiler::results() const {
  std::vector<ScopeTime> out;
  if (!pool_ || used_ == 0) return out;
  if (!open_.empty()) throw Error("GpuProfiler: scope '" + scopes_[open_.back()].name + "' was never ended");
  std::vector<std::uint64_t> stamps(used_);
  HP_VK_CHECK(fn_->vkGetQueryPoolResults(device_, pool_, 0, used_, stamps.size() * sizeof(std::uint64_t), stamps.data(),
                                    sizeof(std::uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  for (const Scope& s : scopes_) {
    std::uint64_t t0 = stamps[s.beginQuery] & validMask_, t1 = stamps[s.endQuery] & validMask_;
    double ticks = static_cast<double>((t1 - t0) & validMask_);
    out.push_back({s.name, ticks * periodNs_ * 1e-6, s.depth});
  }
  return out;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}
}  // namespace hp::vk
