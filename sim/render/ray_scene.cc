#include "sim/render/ray_scene.h"

#include <limits>
#include <stdexcept>
#include <string>

namespace novelty::sim {

namespace {

// Embree reports errors through a C callback; exceptions must not cross it, so the message is
// kept and thrown by CheckDevice() after the call returns.
void RecordDeviceError(void* user, RTCError code, const char* message) {
  auto* last = static_cast<std::string*>(user);
  *last = "Embree error " + std::to_string(int(code)) + ": " + (message ? message : "");
}

RTCGeometry MakeGeometry(RTCDevice device, const TriangleMesh& m) {
  RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), m.vertices.size()));
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    for (int k = 0; k < 3; ++k) v[3 * i + k] = m.vertices[i][k];
  }
  auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), m.triangles.size()));
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    for (int k = 0; k < 3; ++k) idx[3 * i + k] = static_cast<unsigned>(m.triangles[i][k]);
  }
  rtcCommitGeometry(g);
  return g;
}

RTCRay MakeRay(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double t_near, double t_far) {
  RTCRay r;
  r.org_x = float(o.x());
  r.org_y = float(o.y());
  r.org_z = float(o.z());
  r.dir_x = float(d.x());
  r.dir_y = float(d.y());
  r.dir_z = float(d.z());
  r.tnear = float(t_near);
  r.tfar = float(std::min(t_far, double(std::numeric_limits<float>::max())));
  r.time = 0.0f;
  r.mask = 0xFFFFFFFFu;
  r.id = 0;
  r.flags = 0;
  return r;
}

}  // namespace

RayScene::RayScene() {
  device_ = rtcNewDevice("threads=1");  // we parallelise over image rows ourselves
  if (!device_) throw std::runtime_error("RayScene: Embree device could not be created");
  rtcSetDeviceErrorFunction(device_, RecordDeviceError, &device_error_);
  scene_ = rtcNewScene(device_);
  shadow_scene_ = rtcNewScene(device_);
}

RayScene::~RayScene() {
  rtcReleaseScene(shadow_scene_);
  rtcReleaseScene(scene_);
  rtcReleaseDevice(device_);
}

int RayScene::AddObject(const TriangleMesh& mesh, const Eigen::Isometry3d& pose,
                        const Material& material, int object_id) {
  if (committed_) throw std::logic_error("RayScene::AddObject after Commit");
  if (object_id < 0) throw std::invalid_argument("RayScene::AddObject: object_id must be >= 0");
  const std::string what = "mesh of object " + std::to_string(object_id);
  mesh.Check(what.c_str());
  Instance inst{mesh.Transformed(pose), material, object_id};
  const unsigned index = static_cast<unsigned>(instances_.size());
  RTCGeometry g = MakeGeometry(device_, inst.mesh);
  rtcAttachGeometryByID(scene_, g, index);
  if (material.kind != Material::Kind::kGlass) {
    RTCGeometry gs = MakeGeometry(device_, inst.mesh);
    rtcAttachGeometryByID(shadow_scene_, gs, index);
    rtcReleaseGeometry(gs);
  }
  rtcReleaseGeometry(g);
  instances_.push_back(std::move(inst));
  CheckDevice(what.c_str());
  return static_cast<int>(index);
}

void RayScene::Commit() {
  rtcCommitScene(scene_);
  rtcCommitScene(shadow_scene_);
  CheckDevice("RayScene::Commit");
  committed_ = true;
}

void RayScene::CheckDevice(const char* what) {
  if (device_error_.empty()) return;
  const std::string message = std::string(what) + ": " + device_error_;
  device_error_.clear();
  throw std::runtime_error(message);
}

RayHit RayScene::Intersect(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double t_near,
                           double t_far) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  rh.ray = MakeRay(origin, dir, t_near, t_far);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rh);
  RayHit hit;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  const Instance& inst = instances_[rh.hit.geomID];
  const Eigen::Vector3i& tri = inst.mesh.triangles[rh.hit.primID];
  const float u = rh.hit.u, v = rh.hit.v, w = 1.0f - u - v;  // barycentrics of vertices 1, 2, 0
  hit.object = inst.object_id;
  hit.instance = static_cast<int>(rh.hit.geomID);
  hit.t = rh.ray.tfar;
  hit.point = origin + hit.t * dir;
  hit.normal = (w * inst.mesh.normals[tri[0]] + u * inst.mesh.normals[tri[1]] +
                v * inst.mesh.normals[tri[2]])
                   .cast<double>()
                   .normalized();
  hit.geometric = Eigen::Vector3d(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z).normalized();
  hit.uv = w * inst.mesh.uvs[tri[0]] + u * inst.mesh.uvs[tri[1]] + v * inst.mesh.uvs[tri[2]];
  return hit;
}

bool RayScene::Occluded(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double t_near,
                        double t_far) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = MakeRay(origin, dir, t_near, t_far);
  rtcOccluded1(shadow_scene_, &context, &ray);
  return ray.tfar < 0.0f;  // Embree sets tfar = -inf on occlusion
}

}  // namespace novelty::sim
