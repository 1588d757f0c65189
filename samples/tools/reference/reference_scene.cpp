#include "samples/tools/reference/reference_scene.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>

#include "engine/core/error.h"

namespace hp::reference {
namespace {
// A tube's exit: the hit point lies on the side of the segment's axis (at the hit's curve parameter) that
// the ray is heading to. Embree reports the back of round curves too.
void ignoreTubeExits(const RTCFilterFunctionNArguments* args) {
  const auto* scene = static_cast<const ReferenceScene*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    const glm::vec3 o(RTCRayN_org_x(args->ray, args->N, i), RTCRayN_org_y(args->ray, args->N, i),
                      RTCRayN_org_z(args->ray, args->N, i));
    const glm::vec3 d(RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                      RTCRayN_dir_z(args->ray, args->N, i));
    const glm::vec3 p = o + RTCRayN_tfar(args->ray, args->N, i) * d;
    const glm::vec3 axis = scene->axisAt(RTCHitN_primID(args->hit, args->N, i), RTCHitN_u(args->hit, args->N, i));
    if (glm::dot(p - axis, d) > 0.0f) args->valid[i] = 0;
  }
}

void check(RTCDevice device, const char* what) {
  const RTCError e = rtcGetDeviceError(device);
  if (e != RTC_ERROR_NONE) throw Error(std::string("Embree: ") + what + " failed (error " + std::to_string(int(e)) + ")");
}

RTCRayHit makeRay(const glm::dvec3& o, const glm::dvec3& d, float tnear, float tfar) {
  RTCRayHit r{};
  r.ray.org_x = float(o.x), r.ray.org_y = float(o.y), r.ray.org_z = float(o.z);
  r.ray.dir_x = float(d.x), r.ray.dir_y = float(d.y), r.ray.dir_z = float(d.z);
  r.ray.tnear = tnear;
  r.ray.tfar = tfar;
  r.ray.mask = 0xFFFFFFFFu;
  r.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  r.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return r;
}
}  // namespace

glm::dvec3 fibreExitOrigin(const SceneHit& h, const glm::dvec3& dir) {
  glm::dvec3 side = dir - glm::dot(dir, h.tangent) * h.tangent;
  if (glm::dot(side, side) < 1e-12) {  // along the axis: any side (the tube's exit is not a hit)
    side = glm::cross(h.tangent, std::abs(h.tangent.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0));
  }
  return h.axisPoint + (1.0 + 1e-3) * h.radius * glm::normalize(side);  // just outside: no grazing self-hit
}

glm::vec3 ReferenceScene::axisAt(std::uint32_t segment, float u) const {
  const std::uint32_t i = segmentFirst_[segment];
  return glm::mix(glm::vec3(curvePoints_[i]), glm::vec3(curvePoints_[i + 1]), u);
}

ReferenceScene::ReferenceScene(const ExportedFrame& frame) {
  device_ = rtcNewDevice(nullptr);
  if (!device_) throw Error("Embree: cannot create a device");
  scene_ = rtcNewScene(device_);
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  addStrands(frame.strands);
  addHead(frame);
  rtcCommitScene(scene_);
  check(device_, "building the scene");
  RTCBounds b;
  rtcGetSceneBounds(scene_, &b);
  scale_ = glm::length(glm::vec3(b.upper_x - b.lower_x, b.upper_y - b.lower_y, b.upper_z - b.lower_z));
}

ReferenceScene::~ReferenceScene() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

void ReferenceScene::addStrands(const HairFileData& strands) {
  const auto offsets = strands.strandOffsets();
  for (std::uint32_t s = 0; s < strands.strandCount; ++s) {
    const std::uint32_t first = offsets[s], last = offsets[s + 1] - 1;
    for (std::uint32_t i = first; i <= last; ++i) {
      curvePoints_.emplace_back(strands.points[i], 0.5f * strands.thickness[i]);
      const glm::vec3 d = strands.points[std::min(i + 1, last)] - strands.points[i > first ? i - 1 : i];
      curveTangents_.push_back(glm::length(d) > 0.0f ? glm::normalize(d) : glm::vec3(0, 1, 0));
      if (i < last) {
        segmentFirst_.push_back(i);
        segmentStrand_.push_back(s);
      }
    }
  }
  RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE);
  auto* v = static_cast<glm::vec4*>(
      rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, sizeof(glm::vec4), curvePoints_.size()));
  auto* idx = static_cast<std::uint32_t*>(
      rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(std::uint32_t), segmentFirst_.size()));
  check(device_, "allocating the strand buffers");
  std::memcpy(v, curvePoints_.data(), curvePoints_.size() * sizeof(glm::vec4));
  std::memcpy(idx, segmentFirst_.data(), segmentFirst_.size() * sizeof(std::uint32_t));
  rtcSetGeometryUserData(g, this);
  rtcSetGeometryIntersectFilterFunction(g, ignoreTubeExits);
  rtcSetGeometryOccludedFilterFunction(g, ignoreTubeExits);
  rtcCommitGeometry(g);
  curveGeom_ = rtcAttachGeometry(scene_, g);
  rtcReleaseGeometry(g);
}

void ReferenceScene::addHead(const ExportedFrame& frame) {
  headPositions_ = frame.headPositions;
  headNormals_ = frame.headNormals;
  headAlbedo_ = frame.headAlbedo;
  headIndices_ = frame.headIndices;
  RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                        3 * sizeof(float), headPositions_.size()));
  auto* idx = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                  3 * sizeof(std::uint32_t), headIndices_.size() / 3));
  check(device_, "allocating the head buffers");
  std::memcpy(v, headPositions_.data(), headPositions_.size() * sizeof(glm::vec3));
  std::memcpy(idx, headIndices_.data(), headIndices_.size() * sizeof(std::uint32_t));
  rtcCommitGeometry(g);
  headGeom_ = rtcAttachGeometry(scene_, g);
  rtcReleaseGeometry(g);
}

SceneHit ReferenceScene::fibreHit(std::uint32_t segment, float u, const glm::dvec3& point) const {
  const std::uint32_t i = segmentFirst_[segment];
  const glm::dvec4 a = curvePoints_[i], b = curvePoints_[i + 1];
  SceneHit h;
  h.kind = SceneHit::Kind::Fibre;
  h.point = point;
  h.strand = segmentStrand_[segment];
  const glm::dvec3 t = glm::mix(glm::dvec3(curveTangents_[i]), glm::dvec3(curveTangents_[i + 1]), double(u));
  h.tangent = glm::length(t) > 0.0 ? glm::normalize(t) : glm::normalize(glm::dvec3(b - a) + 1e-30);
  h.radius = glm::mix(a.w, b.w, double(u));
  h.axisPoint = glm::mix(glm::dvec3(a), glm::dvec3(b), double(u));
  return h;
}

SceneHit ReferenceScene::headHit(std::uint32_t triangle, float u, float v, const glm::dvec3& ng) const {
  const std::uint32_t* tri = &headIndices_[std::size_t(triangle) * 3];
  const double w0 = 1.0 - u - v;
  SceneHit h;
  h.kind = SceneHit::Kind::Head;
  const glm::dvec3 n = w0 * glm::dvec3(headNormals_[tri[0]]) + double(u) * glm::dvec3(headNormals_[tri[1]]) +
                       double(v) * glm::dvec3(headNormals_[tri[2]]);
  h.geometricNormal = glm::normalize(ng);
  h.normal = glm::length(n) > 0.0 ? glm::normalize(n) : h.geometricNormal;
  h.albedo = w0 * glm::dvec3(headAlbedo_[tri[0]]) + double(u) * glm::dvec3(headAlbedo_[tri[1]]) +
             double(v) * glm::dvec3(headAlbedo_[tri[2]]);
  return h;
}

SceneHit ReferenceScene::intersect(const glm::dvec3& origin, const glm::dvec3& dir, float tnear) const {
  RTCIntersectContext c;
  rtcInitIntersectContext(&c);
  RTCRayHit r = makeRay(origin, dir, tnear, std::numeric_limits<float>::infinity());
  rtcIntersect1(scene_, &c, &r);
  if (r.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {};
  const glm::dvec3 point = origin + double(r.ray.tfar) * dir;
  SceneHit h = r.hit.geomID == curveGeom_ ? fibreHit(r.hit.primID, r.hit.u, point)
                                          : headHit(r.hit.primID, r.hit.u, r.hit.v, {r.hit.Ng_x, r.hit.Ng_y, r.hit.Ng_z});
  h.t = r.ray.tfar;
  h.point = point;
  return h;
}

bool ReferenceScene::occluded(const glm::dvec3& origin, const glm::dvec3& dir, float tnear, float tfar) const {
  RTCIntersectContext c;
  rtcInitIntersectContext(&c);
  RTCRay r = makeRay(origin, dir, tnear, tfar).ray;
  rtcOccluded1(scene_, &c, &r);
  return r.tfar < 0.0f;  // Embree sets tfar = -inf on a hit
}
}  // namespace hp::reference
