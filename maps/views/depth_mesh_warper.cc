#include "maps/views/depth_mesh_warper.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <opencv2/core/utility.hpp>
#include <stdexcept>
#include <utility>
#include <vector>

#include "maps/views/reference_view_store.h"

namespace novelty::views {

namespace {

// A source vertex in the virtual camera: screen position, 1/z, and the source depth (for the
// discontinuity test). inv_z = 0 marks an unusable vertex.
struct Vertex {
  float x, y, inv_z, source_depth;
};

// All source vertices, structure of arrays (contiguous loads for the vectorised rasteriser).
struct Vertices {
  std::vector<float> x, y, inv_z, source_depth;
  void Resize(std::size_t n) {
    x.resize(n);
    y.resize(n);
    inv_z.resize(n);
    source_depth.resize(n);
  }
  Vertex operator[](std::size_t i) const { return {x[i], y[i], inv_z[i], source_depth[i]}; }
};

// Runs fn(begin, end) over [0, n) split into `blocks` stripes on OpenCV's persistent thread pool
// (no thread is created per call).
void ParallelBlocks(int n, int blocks, const std::function<void(int, int)>& fn) {
  cv::parallel_for_(
      cv::Range(0, n), [&](const cv::Range& r) { fn(r.start, r.end); }, blocks);
}

int ThreadCount(int requested) {
  return requested > 0 ? requested : std::max(1, cv::getNumThreads());
}

// Projects every source pixel into the virtual camera (eq. 3.6, 3.9 and the virtual projection).
void ProjectVertices(const PinholeCamera& src, const Eigen::Isometry3d& T_vs, const cv::Mat& depth,
                     const PinholeCamera& dst, double near_plane, int threads, Vertices& v) {
  v.Resize(static_cast<std::size_t>(src.width) * src.height);
  const Eigen::Matrix3f R = T_vs.linear().cast<float>();
  const Eigen::Vector3f t = T_vs.translation().cast<float>();
  // R · K⁻¹ (u, v, 1) is affine in u and v: a·u + b·v + c.
  const Eigen::Vector3f a = R.col(0) / float(src.fx), b = R.col(1) / float(src.fy);
  const Eigen::Vector3f c = R.col(2) - a * float(src.cx) - b * float(src.cy);
  const float fx = float(dst.fx), fy = float(dst.fy), cx = float(dst.cx), cy = float(dst.cy);
  const float near_z = float(near_plane);
  ParallelBlocks(src.height, ThreadCount(threads), [&](int r0, int r1) {
    for (int r = r0; r < r1; ++r) {
      const float* d = depth.ptr<float>(r);
      const std::size_t base = std::size_t(r) * src.width;
      using Row = Eigen::Map<Eigen::ArrayXf>;
      const Eigen::Map<const Eigen::ArrayXf> z_src(d, src.width);
      const Eigen::Vector3f row = b * float(r) + c;
      const Eigen::ArrayXf us = Eigen::ArrayXf::LinSpaced(src.width, 0.0f, float(src.width - 1));
      // p = z · (a·u + row) + t, per coordinate, for the whole row at once.
      const Eigen::ArrayXf px = z_src * (a.x() * us + row.x()) + t.x();
      const Eigen::ArrayXf py = z_src * (a.y() * us + row.y()) + t.y();
      const Eigen::ArrayXf pz = z_src * (a.z() * us + row.z()) + t.z();
      // Valid: positive depth (NaN fails) and in front of the near plane.
      const Eigen::Array<bool, Eigen::Dynamic, 1> ok = (z_src > 0.0f) && (pz > near_z);
      const Eigen::ArrayXf iz = ok.select(pz.inverse(), 0.0f);
      Row(&v.x[base], src.width) = fx * px * iz + cx;
      Row(&v.y[base], src.width) = fy * py * iz + cy;
      Row(&v.inv_z[base], src.width) = iz;
      Row(&v.source_depth[base], src.width) = ok.select(z_src, 0.0f);
    }
  });
}

// The rasteriser's output for one thread: inverse depth (the z-buffer, 0 = empty — nearer is
// larger, so no division per pixel), source depth and source coordinates.
struct Target {
  cv::Mat inv_z, source_depth, uv;
  // Sizes (reusing the memory of an earlier call) and clears the z-buffer; the other buffers
  // are only read where the z-buffer was written, so they need no clearing.
  void Reset(int rows, int cols) {
    inv_z.create(rows, cols, CV_32FC1);
    source_depth.create(rows, cols, CV_32FC1);
    uv.create(rows, cols, CV_32FC2);
    inv_z.setTo(0.0f);
  }
  // Keeps, per pixel, the nearer of this and `other`.
  void Merge(const Target& other) {
    const cv::Mat nearer = other.inv_z > inv_z;
    other.inv_z.copyTo(inv_z, nearer);
    other.source_depth.copyTo(source_depth, nearer);
    other.uv.copyTo(uv, nearer);
  }
};

// Rasterises one triangle with vertices a, b, c (source pixel coordinates sa, sb, sc) into the
// pixels [x0, x1] × [y0, y1] (already clipped to the image). Pixel centres at integer
// coordinates; 1/z and the source coordinates are interpolated linearly on screen.
inline __attribute__((always_inline)) void Rasterise(const Vertex& a, const Vertex& b,
                                                     const Vertex& c, const cv::Vec2f& sa,
                                                     const cv::Vec2f& sb, const cv::Vec2f& sc,
                                                     int x0, int x1, int y0, int y1, float* iz_buf,
                                                     float* zs_buf, cv::Vec2f* uv_buf, int width) {
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
      const float iz = wa * a.inv_z + wb * b.inv_z + wc * c.inv_z;
      const std::size_t i = std::size_t(y) * width + x;
      if (iz <= iz_buf[i]) continue;  // z-test on inverse depth
      iz_buf[i] = iz;
      zs_buf[i] = wa * a.source_depth + wb * b.source_depth + wc * c.source_depth;
      uv_buf[i] = wa * sa + wb * sb + wc * sc;
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

// Buffers of one thread's target, as raw pointers, with the virtual image size.
struct TargetView {
  float* iz;
  float* zs;
  cv::Vec2f* uv;
  int width, height;
};

// The general case: one quad (source pixels (u, r)…(u+1, r+1)) as two triangles.
void RasteriseQuad(const Vertices& v, int w, int u, int r, float max_ratio, const TargetView& t) {
  const std::size_t i = std::size_t(r) * w + u;
  const Vertex p00 = v[i], p10 = v[i + 1], p01 = v[i + w], p11 = v[i + w + 1];
  // The quad's pixel-centre bounding box, clipped to the image.
  const float qx0 = std::min(std::min(p00.x, p10.x), std::min(p01.x, p11.x));
  const float qx1 = std::max(std::max(p00.x, p10.x), std::max(p01.x, p11.x));
  const float qy0 = std::min(std::min(p00.y, p10.y), std::min(p01.y, p11.y));
  const float qy1 = std::max(std::max(p00.y, p10.y), std::max(p01.y, p11.y));
  const int x0 = std::max(0, int(std::ceil(qx0)));
  const int x1 = std::min(t.width - 1, int(std::floor(qx1)));
  const int y0 = std::max(0, int(std::ceil(qy0)));
  const int y1 = std::min(t.height - 1, int(std::floor(qy1)));
  if (x0 > x1 || y0 > y1) return;
  const float fu = float(u), fr = float(r);
  const cv::Vec2f s00{fu, fr}, s10{fu + 1, fr}, s01{fu, fr + 1}, s11{fu + 1, fr + 1};
  if (Usable(p00, p10, p11, max_ratio)) {
    Rasterise(p00, p10, p11, s00, s10, s11, x0, x1, y0, y1, t.iz, t.zs, t.uv, t.width);
  }
  if (Usable(p00, p11, p01, max_ratio)) {
    Rasterise(p00, p11, p01, s00, s11, s01, x0, x1, y0, y1, t.iz, t.zs, t.uv, t.width);
  }
}

// Sixteen quads of one row at a time. Between views of similar resolution most quads have a
// pixel-centre bounding box with exactly one pixel centre or none; such lanes are decided with
// SIMD arithmetic — the same formulas as Rasterise — and only their z-test and write are scalar.
// Lanes whose box holds more pixels go through RasteriseQuad.
void RasteriseRowVectorised(const Vertices& v, int w, int r, float max_ratio, const TargetView& t) {
  constexpr int kLanes = 16;
  using P = Eigen::Array<float, kLanes, 1>;
  using B = Eigen::Array<bool, kLanes, 1>;  // masks evaluated: expressions would dangle
  using M = Eigen::Map<const P, Eigen::Unaligned>;
  const std::size_t base = std::size_t(r) * w;
  const float eps = -1e-5f;
  int u = 0;
  for (; u + kLanes < w; u += kLanes) {
    const std::size_t i = base + u;
    const P x00 = M(&v.x[i]), x10 = M(&v.x[i + 1]), x01 = M(&v.x[i + w]), x11 = M(&v.x[i + w + 1]);
    const P y00 = M(&v.y[i]), y10 = M(&v.y[i + 1]), y01 = M(&v.y[i + w]), y11 = M(&v.y[i + w + 1]);
    const P bx0 = x00.min(x10).min(x01.min(x11)).ceil().max(0.0f);
    const P bx1 = x00.max(x10).max(x01.max(x11)).floor().min(float(t.width - 1));
    const P by0 = y00.min(y10).min(y01.min(y11)).ceil().max(0.0f);
    const P by1 = y00.max(y10).max(y01.max(y11)).floor().min(float(t.height - 1));
    const B empty = (bx0 > bx1) || (by0 > by1) || !(bx0 == bx0);  // NaN-safe
    if (empty.all()) continue;
    const B single = (bx0 == bx1) && (by0 == by1);
    const P i00 = M(&v.inv_z[i]), i10 = M(&v.inv_z[i + 1]), i01 = M(&v.inv_z[i + w]),
            i11 = M(&v.inv_z[i + w + 1]);
    const P z00 = M(&v.source_depth[i]), z10 = M(&v.source_depth[i + 1]),
            z01 = M(&v.source_depth[i + w]), z11 = M(&v.source_depth[i + w + 1]);
    // Weights of b and c at the candidate pixel (bx0, by0) for triangle (00, b, c).
    auto weights = [&](const P& bx, const P& by, const P& cx, const P& cy, P& wb, P& wc) -> B {
      const P area = (bx - x00) * (cy - y00) - (by - y00) * (cx - x00);
      const P inv_area = area.inverse();
      wb = ((bx0 - x00) * (cy - y00) - (by0 - y00) * (cx - x00)) * inv_area;
      wc = ((bx - x00) * (by0 - y00) - (by - y00) * (bx0 - x00)) * inv_area;
      return area.abs() >= 1e-12f;
    };
    auto usable = [&](const P& ib, const P& ic, const P& zb, const P& zc) -> B {
      return (i00 != 0.0f) && (ib != 0.0f) && (ic != 0.0f) &&
             (z00.max(zb).max(zc) <= z00.min(zb).min(zc) * max_ratio);
    };
    P wbA, wcA, wbB, wcB;
    const B okA = weights(x10, y10, x11, y11, wbA, wcA) && usable(i10, i11, z10, z11);
    const B okB = weights(x11, y11, x01, y01, wbB, wcB) && usable(i11, i01, z11, z01);
    const P waA = 1.0f - wbA - wcA, waB = 1.0f - wbB - wcB;
    const B inA = okA && (waA >= eps) && (wbA >= eps) && (wcA >= eps);
    const B inB = okB && (waB >= eps) && (wbB >= eps) && (wcB >= eps);
    const P wa = inA.select(waA, waB), wb = inA.select(wbA, wbB), wc = inA.select(wcA, wcB);
    const P iz = wa * i00 + wb * inA.select(i10, i11) + wc * inA.select(i11, i01);
    const P zs = wa * z00 + wb * inA.select(z10, z11) + wc * inA.select(z11, z01);
    const P su = wb + inA.select(wc, P::Zero());  // offsets from (u, r) in the source
    const P sv = inA.select(wc, wb + wc);
    for (int k = 0; k < kLanes; ++k) {
      if (empty[k]) continue;
      if (!single[k]) {
        RasteriseQuad(v, w, u + k, r, max_ratio, t);
        continue;
      }
      if (!inA[k] && !inB[k]) continue;
      const std::size_t j = std::size_t(by0[k]) * t.width + std::size_t(bx0[k]);
      if (iz[k] <= t.iz[j]) continue;  // z-test on inverse depth
      t.iz[j] = iz[k];
      t.zs[j] = zs[k];
      t.uv[j] = cv::Vec2f(float(u + k) + su[k], float(r) + sv[k]);
    }
  }
  for (; u + 1 < w; ++u) RasteriseQuad(v, w, u, r, max_ratio, t);
}

}  // namespace

struct DepthMeshWarper::Scratch {
  Vertices vertices;
  std::vector<Target> targets;
  cv::Mat covered;
};

DepthMeshWarper::DepthMeshWarper(const WarpOptions& options)
    : options_(options), scratch_(std::make_unique<Scratch>()) {}
DepthMeshWarper::~DepthMeshWarper() = default;

void DepthMeshWarper::Warp(const PinholeCamera& src, const Eigen::Isometry3d& T_world_src,
                           const cv::Mat& depth, const PinholeCamera& dst,
                           const Eigen::Isometry3d& T_world_dst, WarpField& field) {
  const WarpOptions& o = options_;
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
  Vertices& v = scratch_->vertices;
  ProjectVertices(src, T_vs, depth, dst, o.near_plane, o.threads, v);

  // Threads take blocks of source rows, each with its own buffers, merged by depth afterwards.
  const int n_threads = std::max(1, std::min(src.height - 1, ThreadCount(o.threads)));
  std::vector<Target>& targets = scratch_->targets;
  targets.resize(std::size_t(n_threads));
  for (Target& t : targets) t.Reset(dst.height, dst.width);
  const float max_ratio = float(1.0 + o.max_relative_depth_jump);
  const int w = src.width;
  ParallelBlocks(n_threads, n_threads, [&](int t0, int t1) {
    for (int ti = t0; ti < t1; ++ti) {
      Target& t = targets[std::size_t(ti)];
      float* iz_buf = t.inv_z.ptr<float>();
      float* zs_buf = t.source_depth.ptr<float>();
      cv::Vec2f* uv_buf = t.uv.ptr<cv::Vec2f>();
      const int r_begin = (src.height - 1) * ti / n_threads;
      const int r_end = (src.height - 1) * (ti + 1) / n_threads;
      const TargetView view{iz_buf, zs_buf, uv_buf, dst.width, dst.height};
      for (int r = r_begin; r < r_end; ++r) {
        if (o.vectorised) {
          RasteriseRowVectorised(v, w, r, max_ratio, view);
        } else {
          for (int u = 0; u + 1 < w; ++u) RasteriseQuad(v, w, u, r, max_ratio, view);
        }
      }
    }
  });
  for (std::size_t i = 1; i < targets.size(); ++i) targets[0].Merge(targets[i]);

  Target& t = targets[0];
  cv::Mat& covered = scratch_->covered;
  cv::compare(t.inv_z, 0.0f, covered, cv::CMP_GT);
  cv::divide(1.0, t.inv_z, field.depth);
  // The target's buffers become the field's (and the field's old ones the next scratch).
  std::swap(field.source_depth, t.source_depth);
  std::swap(field.map, t.uv);
  const cv::Mat uncovered = ~covered;
  field.depth.setTo(0.0f, uncovered);  // 0, not 1/0
  field.source_depth.setTo(0.0f, uncovered);
  field.map.setTo(cv::Scalar(-1, -1), uncovered);
  field.covered = cv::countNonZero(covered);
  if (o.compute_view_angles) field.cos_angle = ViewAngles(field.depth, dst, T_vs.translation());
}

WarpField WarpView(const PinholeCamera& source_camera, const Eigen::Isometry3d& T_world_source,
                   const cv::Mat& source_depth, const PinholeCamera& virtual_camera,
                   const Eigen::Isometry3d& T_world_virtual, const WarpOptions& options) {
  WarpField field;
  DepthMeshWarper(options).Warp(source_camera, T_world_source, source_depth, virtual_camera,
                                T_world_virtual, field);
  return field;
}

}  // namespace novelty::views
