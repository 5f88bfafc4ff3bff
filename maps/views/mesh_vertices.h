// A source view's depth map as mesh vertices seen from the virtual camera (3.3.2): every source
// pixel back-projected with its depth and projected into the virtual camera (eq. 3.6, 3.9),
// sixteen at a time. Part of DepthMeshWarper (depth_mesh_warper.h); the rasterisers
// (quad_rasteriser.h, block_rasteriser.h) draw the mesh between these vertices.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "core/eigen_abi.h"
#include "core/lanes.h"
#include "core/pinhole_camera.h"
#include "maps/views/mesh_plan.h"

namespace novelty::views::mesh {

using namespace core::lanes;  // F16, I16, Load, Min… (core/lanes.h)

// A source vertex in the virtual camera: screen position, 1/z, and the source depth (for the
// discontinuity test). inv_z = 0 marks an unusable vertex.
struct Vertex {
  float x, y, inv_z, source_depth;
};

// All source vertices, structure of arrays (contiguous loads for the vectorised rasteriser). Only
// the vertices something draws from are projected at a warp (WarpWith); the others keep values
// of an earlier warp, read only by lanes that are masked out. `skip` is the view's plan's
// (mesh_plan.h): per quad, indexed by its top-left vertex, −1 where it is not drawn on its own.
struct Vertices {
  std::vector<float> x, y, inv_z, source_depth;
  const int8_t* skip = nullptr;
  // n vertices, and padding that SIMD loads past the last one may read (never drawn: 1/z = 0).
  void Resize(std::size_t n) {
    x.resize(n + kPadding);
    y.resize(n + kPadding);
    inv_z.resize(n + kPadding);
    source_depth.resize(n + kPadding);
    std::fill(inv_z.begin() + std::ptrdiff_t(n), inv_z.end(), 0.0f);
  }
  static constexpr std::size_t kPadding = MeshPlan::kPadding;
  Vertex operator[](std::size_t i) const { return {x[i], y[i], inv_z[i], source_depth[i]}; }
};

// One source pixel (T = float) or sixteen (T = F16) projected into the virtual camera:
// p = z · (a·u + row) + t (eq. 3.6, 3.9), then the virtual projection. Unusable vertices (depth
// not positive or not finite, behind the near plane) get 1/z = 0 and screen position −1, never NaN.
struct Projection {
  float ax, ay, az, tx, ty, tz, fx, fy, cx, cy, near_z;
  template <typename T>
  void operator()(T z, T fu, float rx, float ry, float rz, float* X, float* Y, float* IZ,
                  float* SD) const {
    const T px = z * (ax * fu + rx) + tx;
    const T py = z * (ay * fu + ry) + ty;
    const T pz = z * (az * fu + rz) + tz;
    const auto ok = (z > 0.0f) & (z < 1e30f) & (pz > near_z);
    const T iz = Select(ok, Reciprocal(pz), T{});
    Put(X, Select(ok, fx * px * iz + cx, T{} - 1.0f));
    Put(Y, Select(ok, fy * py * iz + cy, T{} - 1.0f));
    Put(IZ, iz);
    Put(SD, Select(ok, z, T{}));
  }
  static void Put(float* p, float v) { *p = v; }
  static void Put(float* p, F16 v) { Store(p, v); }
};

// Projects source pixels into the virtual camera, sixteen at a time, a row at a time.
class VertexProjector {
 public:
  VertexProjector(const core::PinholeCamera& src, const Eigen::Isometry3d& T_vs,
                  const cv::Mat& depth, const core::PinholeCamera& dst, double near_plane,
                  Vertices& v)
      : depth_(depth), v_(v), width_(src.width) {
    const Eigen::Matrix3f R = T_vs.linear().cast<float>();
    const Eigen::Vector3f t = T_vs.translation().cast<float>();
    // R · K⁻¹ (u, v, 1) is affine in u and v: a·u + b·v + c.
    const Eigen::Vector3f a = R.col(0) / float(src.fx);
    b_ = R.col(1) / float(src.fy);
    c_ = R.col(2) - a * float(src.cx) - b_ * float(src.cy);
    project_ = {a.x(),
                a.y(),
                a.z(),
                t.x(),
                t.y(),
                t.z(),
                float(dst.fx),
                float(dst.fy),
                float(dst.cx),
                float(dst.cy),
                float(near_plane)};
  }

  // Row r: every vertex (all), or only the groups of sixteen that a quad drawn on its own uses
  // (Vertices::skip of the quads in rows r − 1 and r, columns u − 1 … u + 15). Planar runs read
  // only their corners, which lie on block rows, where the caller asks for all.
  void Row(int r, bool all) const {
    const float* d = depth_.ptr<float>(r);
    const std::size_t base = std::size_t(r) * width_;
    const Eigen::Vector3f row = b_ * float(r) + c_;
    const F16 lane_u = core::lanes::Iota();
    int u = 0;
    for (; u + kLanes <= width_; u += kLanes) {
      if (!all && !Needed(r, u)) continue;
      project_(Load(d + u), lane_u + float(u), row.x(), row.y(), row.z(), &v_.x[base + u],
               &v_.y[base + u], &v_.inv_z[base + u], &v_.source_depth[base + u]);
    }
    for (; u < width_; ++u) {
      project_(d[u], float(u), row.x(), row.y(), row.z(), &v_.x[base + u], &v_.y[base + u],
               &v_.inv_z[base + u], &v_.source_depth[base + u]);
    }
  }

 private:
  bool Needed(int r, int u) const {
    for (const int qr : {r - 1, r}) {
      if (qr < 0) continue;
      const int8_t* skip = &v_.skip[std::size_t(qr) * width_ + u];
      if (core::lanes::Any(core::lanes::LoadBytes(skip) == 0) || (u > 0 && skip[-1] == 0))
        return true;
    }
    return false;
  }

  const cv::Mat& depth_;
  Vertices& v_;
  int width_;
  Eigen::Vector3f b_, c_;
  Projection project_;
};

}  // namespace novelty::views::mesh
