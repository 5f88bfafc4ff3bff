// The renderable world: triangle meshes placed in world coordinates with a material and an
// object id, in an Embree 3 BVH for ray intersection and shadow (occlusion) queries.
#pragma once

#include <embree3/rtcore.h>

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "sim/render/material.h"
#include "sim/render/triangle_mesh.h"

namespace novelty::sim {

/// What a ray hit. `object` is the id given to AddObject; kNoObject if nothing was hit.
struct RayHit {
  static constexpr int kNoObject = -1;
  int object = kNoObject;
  int instance = -1;          ///< index of the object in insertion order
  double t = 0.0;             ///< ray parameter at the hit
  Eigen::Vector3d point;      ///< world coordinates
  Eigen::Vector3d normal;     ///< interpolated shading normal, unit, as stored (not flipped)
  Eigen::Vector3d geometric;  ///< geometric normal, unit, from the triangle's winding
  Eigen::Vector2f uv;
};

class RayScene {
 public:
  RayScene();
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  /// Places `mesh` (object coordinates) at `pose` (world ← object). `object_id` ≥ 0 is what the
  /// id image shows; several meshes may share one id. Returns the instance index.
  int AddObject(const TriangleMesh& mesh, const Eigen::Isometry3d& pose, const Material& material,
                int object_id);
  /// Builds the BVH; call after the last AddObject and before any query.
  void Commit();

  /// Nearest hit along origin + t·dir for t in (t_near, t_far).
  RayHit Intersect(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double t_near,
                   double t_far) const;
  /// True if something blocks the segment origin + t·dir, t in (t_near, t_far). Objects whose
  /// material is glass do not cast shadows (the thesis's glass shows refraction, not a shadow).
  bool Occluded(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double t_near,
                double t_far) const;

  const Material& MaterialOf(int instance) const { return instances_[instance].material; }
  int ObjectCount() const { return static_cast<int>(instances_.size()); }

 private:
  struct Instance {
    TriangleMesh mesh;  // world coordinates
    Material material;
    int object_id;
  };
  void CheckDevice(const char* what);

  std::string device_error_;  // set by Embree's error callback
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;         // everything: camera rays
  RTCScene shadow_scene_ = nullptr;  // opaque objects only: shadow rays
  std::vector<Instance> instances_;
  bool committed_ = false;
};

}  // namespace novelty::sim
