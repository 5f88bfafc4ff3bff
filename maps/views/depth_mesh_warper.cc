#include "maps/views/depth_mesh_warper.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <thread>
#include <vector>

#include "maps/views/reference_view_store.h"

namespace novelty::views {

namespace {

// A source vertex in the virtual camera: screen position, 1/z, and the source depth (for the
// discontinuity test). inv_z = 0 marks an unusable vertex.
struct Vertex {
  float x, y, inv_z, source_depth;
};

// Runs fn(begin, end) over [0, n) in one block per thread, the caller taking the first block.
void ParallelBlocks(int n, int threads, const std::function<void(int, int)>& fn) {
  const int t = std::max(
      1,
      std::min(n, threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()))));
  std::vector<std::thread> workers;
  for (int i = 1; i < t; ++i) workers.emplace_back(fn, n * i / t, n * (i + 1) / t);
  fn(0, n / t);
  for (std::thread& w : workers) w.join();
}

// Projects every source pixel into the virtual camera (eq. 3.6, 3.9 and the virtual projection).
std::vector<Vertex> ProjectVertices(const PinholeCamera& src, const Eigen::Isometry3d& T_vs,
                                    const cv::Mat& depth, const PinholeCamera& dst,
                                    double near_plane, int threads) {
  std::vector<Vertex> v(static_cast<std::size_t>(src.width) * src.height);
  const Eigen::Matrix3f R = T_vs.linear().cast<float>();
  const Eigen::Vector3f t = T_vs.translation().cast<float>();
  // R · K⁻¹ (u, v, 1) is affine in u and v: a·u + b·v + c.
  const Eigen::Vector3f a = R.col(0) / float(src.fx), b = R.col(1) / float(src.fy);
  const Eigen::Vector3f c = R.col(2) - a * float(src.cx) - b * float(src.cy);
  const float fx = float(dst.fx), fy = float(dst.fy), cx = float(dst.cx), cy = float(dst.cy);
  const float near_z = float(near_plane);
  ParallelBlocks(src.height, threads, [&](int r0, int r1) {
    for (int r = r0; r < r1; ++r) {
      const float* d = depth.ptr<float>(r);
      Vertex* out = &v[std::size_t(r) * src.width];
      const Eigen::Vector3f row = b * float(r) + c;
      for (int u = 0; u < src.width; ++u) {
        const float z_src = d[u];
        const Eigen::Vector3f p = z_src * (a * float(u) + row) + t;
        if (!(z_src > 0.0f) || !(p.z() > near_z)) {  // also rejects NaN depth
          out[u] = {0.f, 0.f, 0.f, 0.f};
          continue;
        }
        const float iz = 1.0f / p.z();
        out[u] = {fx * p.x() * iz + cx, fy * p.y() * iz + cy, iz, z_src};
      }
    }
  });
  return v;
}

struct Target {
  float* z;       // virtual depth (z-buffer), 0 = empty
  float* zs;      // source depth
  cv::Vec2f* uv;  // source coordinates
  int width, row_begin, row_end;
};

// Rasterises one triangle with vertices a, b, c (source pixel coordinates sa, sb, sc) into the
// pixels [x0, x1] × [y0, y1] (already clipped to the image and the thread's band). Pixel centres
// at integer coordinates; 1/z and the source coordinates are interpolated linearly on screen.
inline __attribute__((always_inline)) void Rasterise(const Vertex& a, const Vertex& b,
                                                     const Vertex& c, const cv::Vec2f& sa,
                                                     const cv::Vec2f& sb, const cv::Vec2f& sc,
                                                     int x0, int x1, int y0, int y1,
                                                     const Target& t) {
  const float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  if (std::abs(area) < 1e-12f) return;
  const float inv_area = 1.0f / area;
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const float px = float(x), py = float(y);
      // Barycentric weights of b and c (edge functions), a gets the rest.
      const float wb = ((px - a.x) * (c.y - a.y) - (py - a.y) * (c.x - a.x)) * inv_area;
      const float wc = ((b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x)) * inv_area;
      const float wa = 1.0f - wb - wc;
      if (wa < -1e-5f || wb < -1e-5f || wc < -1e-5f) continue;
      const float z = 1.0f / (wa * a.inv_z + wb * b.inv_z + wc * c.inv_z);
      const std::size_t i = std::size_t(y) * t.width + x;
      if (t.z[i] != 0.0f && t.z[i] <= z) continue;
      t.z[i] = z;
      t.zs[i] = wa * a.source_depth + wb * b.source_depth + wc * c.source_depth;
      t.uv[i] = wa * sa + wb * sb + wc * sc;
    }
  }
}

inline bool Usable(const Vertex& a, const Vertex& b, const Vertex& c, float max_ratio) {
  if (a.inv_z == 0.f || b.inv_z == 0.f || c.inv_z == 0.f) return false;
  const float lo = std::min(a.source_depth, std::min(b.source_depth, c.source_depth));
  const float hi = std::max(a.source_depth, std::max(b.source_depth, c.source_depth));
  return hi <= lo * max_ratio;
}

// Per covered virtual pixel: cos of the angle between the rays from the surface point to the
// virtual camera centre (origin) and to the source camera centre (in virtual coordinates).
cv::Mat ViewAngles(const cv::Mat& depth, const PinholeCamera& cam, const Eigen::Vector3d& source) {
  cv::Mat cos_angle(depth.size(), CV_32FC1, cv::Scalar(0));
  const Eigen::Vector3f c = source.cast<float>();
  for (int y = 0; y < depth.rows; ++y) {
    const float* z = depth.ptr<float>(y);
    float* out = cos_angle.ptr<float>(y);
    for (int x = 0; x < depth.cols; ++x) {
      if (z[x] <= 0.0f) continue;
      const Eigen::Vector3f p = cam.Unproject(x, y, z[x]).cast<float>();
      out[x] = p.dot(p - c) / (p.norm() * (p - c).norm());
    }
  }
  return cos_angle;
}

}  // namespace

WarpField WarpView(const PinholeCamera& src, const Eigen::Isometry3d& T_world_src,
                   const cv::Mat& depth, const PinholeCamera& dst,
                   const Eigen::Isometry3d& T_world_dst, const WarpOptions& o) {
  src.Check();
  dst.Check();
  if (!IsRigid(T_world_src) || !IsRigid(T_world_dst)) {
    throw std::invalid_argument("WarpView: a camera pose is not a rigid transform");
  }
  if (depth.type() != CV_32FC1 || depth.cols != src.width || depth.rows != src.height) {
    throw std::invalid_argument(
        "WarpView: source depth must be CV_32FC1 of the source camera's "
        "size " +
        std::to_string(src.width) + "x" + std::to_string(src.height));
  }
  const Eigen::Isometry3d T_vs = T_world_dst.inverse() * T_world_src;
  const std::vector<Vertex> v = ProjectVertices(src, T_vs, depth, dst, o.near_plane, o.threads);

  WarpField field;
  field.depth = cv::Mat(dst.height, dst.width, CV_32FC1, cv::Scalar(0));
  field.map = cv::Mat(dst.height, dst.width, CV_32FC2, cv::Scalar(-1, -1));
  field.source_depth = cv::Mat(dst.height, dst.width, CV_32FC1, cv::Scalar(0));
  const float max_ratio = float(1.0 + o.max_relative_depth_jump);
  const int w = src.width;
  ParallelBlocks(dst.height, o.threads, [&](int row_begin, int row_end) {
    const Target t{field.depth.ptr<float>(),
                   field.source_depth.ptr<float>(),
                   field.map.ptr<cv::Vec2f>(),
                   dst.width,
                   row_begin,
                   row_end};
    for (int r = 0; r + 1 < src.height; ++r) {
      for (int u = 0; u + 1 < w; ++u) {
        const std::size_t i = std::size_t(r) * w + u;
        const Vertex &p00 = v[i], &p10 = v[i + 1], &p01 = v[i + w], &p11 = v[i + w + 1];
        // The quad's pixel-centre bounding box, clipped to the image and this band: most quads
        // of a similar-resolution warp hold one pixel centre or none.
        const float qx0 = std::min(std::min(p00.x, p10.x), std::min(p01.x, p11.x));
        const float qx1 = std::max(std::max(p00.x, p10.x), std::max(p01.x, p11.x));
        const float qy0 = std::min(std::min(p00.y, p10.y), std::min(p01.y, p11.y));
        const float qy1 = std::max(std::max(p00.y, p10.y), std::max(p01.y, p11.y));
        const int x0 = std::max(0, int(std::ceil(qx0))),
                  x1 = std::min(t.width - 1, int(std::floor(qx1)));
        const int y0 = std::max(row_begin, int(std::ceil(qy0)));
        const int y1 = std::min(row_end - 1, int(std::floor(qy1)));
        if (x0 > x1 || y0 > y1) continue;
        const float fu = float(u), fr = float(r);
        const cv::Vec2f s00{fu, fr}, s10{fu + 1, fr}, s01{fu, fr + 1}, s11{fu + 1, fr + 1};
        if (Usable(p00, p10, p11, max_ratio))
          Rasterise(p00, p10, p11, s00, s10, s11, x0, x1, y0, y1, t);
        if (Usable(p00, p11, p01, max_ratio))
          Rasterise(p00, p11, p01, s00, s11, s01, x0, x1, y0, y1, t);
      }
    }
  });
  field.covered = cv::countNonZero(field.depth);
  if (o.compute_view_angles) field.cos_angle = ViewAngles(field.depth, dst, T_vs.translation());
  return field;
}

}  // namespace novelty::views
