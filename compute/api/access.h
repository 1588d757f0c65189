#pragma once
// Contract: how hairpipe's implementation of the public API reaches the private state behind its
// handles (hairpipe::Access is the one friend of every public class), and `guarded`, which turns any
// exception of the implementation into the failure a noexcept public call returns.
#include <exception>
#include <memory>
#include <new>
#include <string>

#include "engine/core/error.h"
#include "engine/core/hair/hair_asset.h"
#include "compute/renderer/renderer.h"
#include "engine/vk/context.h"
#include "hairpipe/hairpipe.h"

namespace hairpipe {
// An instance keeps its Renderer's implementation alive: hp::HairInstance refers to it to its end.
struct Instance::Impl {
  std::shared_ptr<hp::Renderer> renderer;
  Asset asset;
  std::unique_ptr<hp::HairInstance> instance;
};

// A raster target keeps its Renderer's implementation alive, as an instance does.
struct RasterTarget::Impl {
  std::shared_ptr<hp::Renderer> renderer;
  std::shared_ptr<hp::RasterTarget> target;
};

struct Access {
  static const hp::vk::Context& context(const Context& c) {
    if (!c.impl_) throw hp::Error("the Context was moved from");
    return *c.impl_;
  }
  static Context makeContext(std::unique_ptr<hp::vk::Context> impl) { return Context(std::move(impl)); }
  static const hp::HairAsset& asset(const Asset& a) {
    if (!a.impl_) throw hp::Error("the Asset was moved from");
    return *a.impl_;
  }
  static Asset makeAsset(hp::HairAsset asset) {
    return Asset(std::make_shared<const hp::HairAsset>(std::move(asset)));
  }
  static Renderer makeRenderer(std::shared_ptr<hp::Renderer> impl) { return Renderer(std::move(impl)); }
  static Instance makeInstance(std::unique_ptr<Instance::Impl> impl) { return Instance(std::move(impl)); }
  static Instance::Impl* impl(const Instance& i) { return i.impl_.get(); }
  static RasterTarget makeRasterTarget(std::unique_ptr<RasterTarget::Impl> impl) { return RasterTarget(std::move(impl)); }
  static RasterTarget::Impl* impl(const RasterTarget& t) { return t.impl_.get(); }
};

// The exception being handled as the failure "WHERE: what()"; called only inside a catch block.
inline Status currentFailure(const char* where) noexcept {
  try {
    throw;
  } catch (const hp::Error& e) {
    return Status::failure(std::string(where) + ": " + e.what());
  } catch (const std::bad_alloc&) {
    return Status::failure(std::string(where) + ": out of host memory");
  } catch (const std::exception& e) {
    return Status::failure(std::string(where) + ": internal error: " + e.what());
  } catch (...) {
    return Status::failure(std::string(where) + ": internal error");
  }
}

// Runs `body`, which returns a T; an exception becomes the failure.
template <class T, class F>
Result<T> guarded(const char* where, F&& body) noexcept {
  try {
    return body();
  } catch (...) {
    return currentFailure(where);
  }
}

// Runs `body`, which returns nothing; an exception becomes the failure.
template <class F>
Status guardedStatus(const char* where, F&& body) noexcept {
  try {
    body();
    return {};
  } catch (...) {
    return currentFailure(where);
  }
}
}  // namespace hairpipe
