#include "samples/tools/reference/path_tracer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <optional>
#include <ostream>
#include <thread>
#include <vector>

#include "engine/core/error.h"
#include "samples/tools/reference/environment_sampler.h"
#include "samples/tools/reference/fibre.h"
#include "samples/tools/reference/fibre_sampling.h"
#include "samples/tools/reference/frame_light.h"
#include "samples/tools/reference/physical_sampling.h"
#include "samples/tools/reference/reference_scene.h"
#include "samples/tools/reference/sampling.h"

namespace hp::reference {
namespace {
constexpr std::uint32_t kTile = 16;
constexpr std::uint32_t kRouletteAfter = 3;

struct Camera {
  glm::dvec3 position, forward, right, up;
  double tanHalf = 0.0, aspect = 1.0;
  std::uint32_t width = 0, height = 0;

  explicit Camera(const FrameCameraSpec& c)
      : position(c.position), width(c.width), height(c.height) {
    forward = glm::normalize(glm::dvec3(c.target) - position);
    right = glm::normalize(glm::cross(forward, glm::dvec3(c.up)));
    up = glm::cross(right, forward);
    tanHalf = std::tan(0.5 * glm::radians(double(c.fovYDeg)));
    aspect = double(c.width) / double(c.height);
  }
  // Image row 0 is the top (+up), as in the rendered PNG.
  glm::dvec3 direction(double px, double py) const {
    const double x = (2.0 * px / width - 1.0) * tanHalf * aspect, y = (1.0 - 2.0 * py / height) * tanHalf;
    return glm::normalize(forward + x * right + y * up);
  }
};

// One path tracer over the frame; trace() is called concurrently for different pixels.
class Tracer {
 public:
  Tracer(const ExportedFrame& frame, const TraceSettings& s)
      : frame_(frame), settings_(s), scene_(frame), camera_(frame.camera),
        model_(parseFibreModel(frame.fibreModel)), colorScales_(frame.strandColorScales()) {
    eps_ = 1e-5f * scene_.sceneScale();
    if (frame.environmentMap) environment_.emplace(*frame.environmentMap);
    if (environment_ && environment_->empty()) environment_.reset();
  }

  // Radiance of one camera sample; `hairFirst` says whether the camera ray hit a fibre first.
  glm::dvec3 trace(std::uint32_t x, std::uint32_t y, std::uint32_t sample, bool& hairFirst) const {
    Sampler rng(settings_.seed, std::uint64_t(y) * camera_.width + x, sample);
    const glm::dvec2 sub = pixelOffset(sample, rng);
    const double px = x + sub.x, py = y + sub.y;
    glm::dvec3 origin = camera_.position, dir = camera_.direction(px, py);
    glm::dvec3 radiance(0.0), throughput(1.0);
    double continuationPdf = 0.0;  // the density the last continuation direction was drawn with
    for (std::uint32_t vertex = 1;; ++vertex) {
      const SceneHit hit = scene_.intersect(origin, dir, 0.0f);
      if (vertex == 1) hairFirst = hit.kind == SceneHit::Kind::Fibre;
      if (hit.kind == SceneHit::Kind::None) {
        radiance += throughput * (vertex == 1 ? glm::dvec3(frame_.background) : skyRadiance(dir, continuationPdf));
        break;
      }
      if (vertex > settings_.bounces) break;  // the last vertex's continuation only gathers the sky
      const glm::dvec3 V = -dir;
      glm::dvec3 weight;
      if (hit.kind == SceneHit::Kind::Fibre) {
        radiance += throughput * (fibreDirect(hit, V) + fibreEnvironment(hit, V, rng));
        weight = sampleFibre(hit, V, rng, origin, dir, continuationPdf);
      } else {
        radiance += throughput * (headDirect(hit, V) + headEnvironment(hit, V, rng));
        weight = sampleHead(hit, V, rng, origin, dir, continuationPdf);
      }
      throughput *= weight;
      if (throughput == glm::dvec3(0.0)) break;
      if (vertex >= kRouletteAfter) {
        const double q = std::min(0.95, std::max({throughput.x, throughput.y, throughput.z}));
        if (!(q > 0.0) || rng.next() >= q) break;
        throughput /= q;
      }
    }
    return radiance;
  }

 private:
  // What a continuation ray drawn with density `pdf` brings when it escapes: the uniform sky, plus the
  // environment map's radiance weighted against the map's own sampling (multiple importance sampling, the
  // power heuristic; next-event estimation takes the rest).
  glm::dvec3 skyRadiance(const glm::dvec3& dir, double pdf) const {
    glm::dvec3 sky(frame_.environment);
    if (!frame_.environmentMap) return sky;
    const double weight = environment_ ? powerHeuristic(pdf, environment_->pdf(dir)) : 1.0;
    return sky + weight * frame_.environmentMap->radiance(dir);
  }

  static double powerHeuristic(double a, double b) { return a * a + b * b > 0.0 ? a * a / (a * a + b * b) : 0.0; }

  // The environment map's light by next-event estimation: one direction drawn from the map, its shadow ray,
  // weighted against the continuation's sampling of the same direction.
  struct EnvironmentArrival {
    glm::dvec3 L, radiance;
    double pdf = 0.0;
  };
  bool sampleEnvironment(Sampler& rng, EnvironmentArrival& a) const {
    if (!environment_) return false;  // no random number drawn: frames without a map trace as before
    a.L = environment_->sample(rng, a.pdf);
    if (!(a.pdf > 0.0)) return false;
    a.radiance = frame_.environmentMap->radiance(a.L);
    return a.radiance != glm::dvec3(0.0);
  }

  glm::dvec3 fibreEnvironment(const SceneHit& h, const glm::dvec3& V, Sampler& rng) const {
    EnvironmentArrival a;
    if (!sampleEnvironment(rng, a)) return glm::dvec3(0.0);
    if (scene_.occluded(fibreExitOrigin(h, a.L), a.L, 0.0f, std::numeric_limits<float>::max())) return glm::dvec3(0.0);
    const double mis = powerHeuristic(a.pdf, fibrePdf(h, V, a.L));
    return fibreS(h, a.L, V) * cosThetaI(a.L, h.tangent) * a.radiance * (mis / a.pdf);
  }

  glm::dvec3 headEnvironment(const SceneHit& h, const glm::dvec3& V, Sampler& rng) const {
    EnvironmentArrival a;
    if (!sampleEnvironment(rng, a)) return glm::dvec3(0.0);
    const glm::dvec3 ng = facing(h.geometricNormal, V), n = facing(h.normal, ng);
    const double cosine = glm::dot(n, a.L);
    if (cosine <= 0.0 || glm::dot(ng, a.L) <= 0.0) return glm::dvec3(0.0);
    if (scene_.occluded(h.point + double(eps_) * ng, a.L, 0.0f, std::numeric_limits<float>::max())) return glm::dvec3(0.0);
    const double mis = powerHeuristic(a.pdf, cosine / kPi);
    return h.albedo / kPi * cosine * a.radiance * (mis / a.pdf);
  }

  double fibrePdf(const SceneHit& h, const glm::dvec3& V, const glm::dvec3& L) const {
    const HairMaterial m = frame_.strandMaterial(h.strand);
    if (model_ == FibreModel::Physical) return PhysicalFibreSampler(h.tangent, V, m).pdf(L);
    return FibreSampler(h.tangent, V, m).pdf(L);
  }

  // Stratified over the pixel when spp is a square (n x n cells, one jittered sample each): strands
  // thinner than a pixel make coverage the main noise, and strata cut it; else uniform.
  glm::dvec2 pixelOffset(std::uint32_t sample, Sampler& rng) const {
    const double u = rng.next(), v = rng.next();
    const auto n = std::uint32_t(std::lround(std::sqrt(double(settings_.spp))));
    if (n * n != settings_.spp) return {u, v};
    return {(sample % n + u) / n, (sample / n + v) / n};
  }

  glm::dvec3 fibreS(const SceneHit& h, const glm::dvec3& L, const glm::dvec3& V) const {
    return reference::fibreS(model_, L, V, h.tangent, frame_.strandMaterial(h.strand)) *
           double(colorScales_[h.strand]);
  }

  static double cosThetaI(const glm::dvec3& L, const glm::dvec3& T) {
    const double s = std::clamp(glm::dot(L, T), -1.0, 1.0);
    return std::sqrt(1.0 - s * s);
  }

  // Next-event estimation of every light, each with its own shadow ray.
  glm::dvec3 fibreDirect(const SceneHit& h, const glm::dvec3& V) const {
    glm::dvec3 sum(0.0);
    for (const LightSpec& light : frame_.lights) {
      const LightArrival a = lightArrival(light, h.axisPoint);
      if (a.irradiance == glm::dvec3(0.0)) continue;
      if (scene_.occluded(fibreExitOrigin(h, a.L), a.L, 0.0f, float(a.distance))) continue;
      sum += fibreS(h, a.L, V) * cosThetaI(a.L, h.tangent) * a.irradiance;
    }
    return sum;
  }

  glm::dvec3 sampleFibre(const SceneHit& h, const glm::dvec3& V, Sampler& rng, glm::dvec3& origin,
                         glm::dvec3& dir, double& pdf) const {
    const HairMaterial m = frame_.strandMaterial(h.strand);
    if (model_ == FibreModel::Physical) return continueFrom(PhysicalFibreSampler(h.tangent, V, m), h, V, rng, origin, dir, pdf);
    return continueFrom(FibreSampler(h.tangent, V, m), h, V, rng, origin, dir, pdf);
  }

  template <class DirectionSampler>
  glm::dvec3 continueFrom(const DirectionSampler& sampler, const SceneHit& h, const glm::dvec3& V, Sampler& rng,
                          glm::dvec3& origin, glm::dvec3& dir, double& pdf) const {
    dir = sampler.sample(rng);
    pdf = 0.0;
    if (dir == glm::dvec3(0.0)) return glm::dvec3(0.0);
    origin = fibreExitOrigin(h, dir);
    pdf = sampler.pdf(dir);
    if (!(pdf > 0.0)) return glm::dvec3(0.0);  // a density that underflowed: S did too (0 / 0)
    return fibreS(h, dir, V) * cosThetaI(dir, h.tangent) / pdf;
  }

  // The side of the surface the viewer is on.
  static glm::dvec3 facing(const glm::dvec3& n, const glm::dvec3& V) { return glm::dot(n, V) >= 0.0 ? n : -n; }

  glm::dvec3 headDirect(const SceneHit& h, const glm::dvec3& V) const {
    const glm::dvec3 ng = facing(h.geometricNormal, V), n = facing(h.normal, ng);
    const glm::dvec3 origin = h.point + double(eps_) * ng;
    glm::dvec3 sum(0.0);
    for (const LightSpec& light : frame_.lights) {
      const LightArrival a = lightArrival(light, h.point);
      const double cosine = glm::dot(n, a.L);
      if (cosine <= 0.0 || glm::dot(ng, a.L) <= 0.0 || a.irradiance == glm::dvec3(0.0)) continue;
      if (scene_.occluded(origin, a.L, 0.0f, float(a.distance))) continue;
      sum += h.albedo / kPi * cosine * a.irradiance;
    }
    return sum;
  }

  glm::dvec3 sampleHead(const SceneHit& h, const glm::dvec3& V, Sampler& rng, glm::dvec3& origin,
                        glm::dvec3& dir, double& pdf) const {
    const glm::dvec3 ng = facing(h.geometricNormal, V), n = facing(h.normal, ng);
    const double u1 = rng.next(), u2 = rng.next();
    dir = cosineHemisphere(n, u1, u2);
    pdf = std::max(glm::dot(n, dir), 0.0) / kPi;
    origin = h.point + double(eps_) * ng;
    return glm::dot(dir, ng) > 0.0 ? h.albedo : glm::dvec3(0.0);
  }

  const ExportedFrame& frame_;
  const TraceSettings& settings_;
  ReferenceScene scene_;
  Camera camera_;
  FibreModel model_;
  std::vector<float> colorScales_;
  std::optional<EnvironmentSampler> environment_;  // the map's next-event sampling; none without a lit map
  float eps_ = 0.0f;
};

class Progress {
 public:
  Progress(std::ostream* out, std::uint32_t tiles, std::uint64_t pathsPerTile)
      : out_(out), tiles_(tiles), pathsPerTile_(pathsPerTile), start_(std::chrono::steady_clock::now()), last_(start_) {}
  void tileDone() {
    const std::uint32_t done = ++done_;
    if (!out_) return;
    std::lock_guard lock(mutex_);
    const auto now = std::chrono::steady_clock::now();
    if (done != tiles_ && now - last_ < std::chrono::seconds(1)) return;
    last_ = now;
    const double s = std::chrono::duration<double>(now - start_).count();
    const double rate = s > 0.0 ? double(done) * double(pathsPerTile_) / s : 0.0;
    const double eta = done > 0 ? s * double(tiles_ - done) / double(done) : 0.0;
    *out_ << "reference: " << done << "/" << tiles_ << " tiles, " << std::lround(rate / 1000.0) << "k paths/s, ETA "
          << std::lround(eta) << " s" << std::endl;
  }

 private:
  std::ostream* out_;
  std::uint32_t tiles_;
  std::uint64_t pathsPerTile_;
  std::atomic<std::uint32_t> done_{0};
  std::mutex mutex_;
  std::chrono::steady_clock::time_point start_, last_;
};

void traceTile(const Tracer& tracer, std::uint32_t tile, std::uint32_t tilesX, const TraceSettings& s,
               TraceResult& out) {
  const std::uint32_t x0 = (tile % tilesX) * kTile, y0 = (tile / tilesX) * kTile;
  const std::uint32_t w = out.radiance.width, h = out.radiance.height;
  for (std::uint32_t y = y0; y < std::min(y0 + kTile, h); ++y)
    for (std::uint32_t x = x0; x < std::min(x0 + kTile, w); ++x) {
      glm::dvec3 sum(0.0);
      std::uint32_t hair = 0;
      for (std::uint32_t i = 0; i < s.spp; ++i) {
        if (i % 1024 == 0 && s.stop && s.stop()) return;  // stopped: the caller discards the image
        bool first = false;
        const glm::dvec3 l = tracer.trace(x, y, i, first);
        if (std::isfinite(l.x + l.y + l.z)) sum += l;
        hair += first ? 1u : 0u;
      }
      for (int c = 0; c < 3; ++c) out.radiance.at(x, y, c) = float(sum[c] / s.spp);
      out.hairCoverage.at(x, y, 0) = float(hair) / float(s.spp);
    }
}
}  // namespace

void TraceSettings::validate() const {
  if (spp < 1 || spp > 1u << 20) throw Error("--spp must be in [1, 1048576]");
  if (bounces < 1 || bounces > 1000) throw Error("--bounces must be in [1, 1000]");
  if (threads > 1024) throw Error("--threads must be at most 1024");
}

TraceResult traceReference(const ExportedFrame& frame, const TraceSettings& settings) {
  settings.validate();
  const auto start = std::chrono::steady_clock::now();
  const Tracer tracer(frame, settings);
  const std::uint32_t w = frame.camera.width, h = frame.camera.height;
  TraceResult out{LinearImage(w, h, 3), LinearImage(w, h, 1)};
  const std::uint32_t tilesX = (w + kTile - 1) / kTile, tiles = tilesX * ((h + kTile - 1) / kTile);
  out.threads = std::min(tiles, settings.threads ? settings.threads : std::max(1u, std::thread::hardware_concurrency()));
  Progress progress(settings.progress, tiles, std::uint64_t(kTile) * kTile * settings.spp);
  std::atomic<std::uint32_t> next{0};
  std::atomic<bool> stopped{false};
  std::exception_ptr failure;
  std::mutex failureMutex;
  auto work = [&] {
    try {
      for (std::uint32_t t; (t = next++) < tiles;) {
        if (settings.stop && settings.stop()) {  // the other threads finish their tile and stop too
          stopped = true;
          next = tiles;
          break;
        }
        traceTile(tracer, t, tilesX, settings, out);
        if (settings.stop && settings.stop()) {  // the tile may have been cut short
          stopped = true;
          next = tiles;
          break;
        }
        progress.tileDone();
      }
    } catch (...) {
      std::lock_guard lock(failureMutex);
      failure = std::current_exception();
      next = tiles;
    }
  };
  std::vector<std::thread> pool;
  for (std::uint32_t i = 1; i < out.threads; ++i) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  if (stopped) throw Error("the trace was stopped before its last tile");
  out.paths = std::uint64_t(w) * h * settings.spp;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}
}  // namespace hp::reference
