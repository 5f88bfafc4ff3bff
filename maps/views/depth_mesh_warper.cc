#include "maps/views/depth_mesh_warper.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <opencv2/core/utility.hpp>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/lanes.h"
#include "core/rigid_pose.h"
#include "maps/views/reference_view_store.h"

namespace novelty::views {

namespace {

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

// Runs fn(begin, end) over [0, n) split into `blocks` stripes on OpenCV's persistent thread pool
// (no thread is created per call).
void ParallelBlocks(int n, int blocks, const std::function<void(int, int)>& fn) {
  cv::parallel_for_(
      cv::Range(0, n), [&](const cv::Range& r) { fn(r.start, r.end); }, blocks);
}

int ThreadCount(int requested) {
  return requested > 0 ? requested : std::max(1, cv::getNumThreads());
}

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
    const T iz = ok ? Reciprocal(pz) : T{};
    Put(X, ok ? fx * px * iz + cx : T{} - 1.0f);
    Put(Y, ok ? fy * py * iz + cy : T{} - 1.0f);
    Put(IZ, iz);
    Put(SD, ok ? z : T{});
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

// What the rasteriser keeps per virtual pixel, in planes so that a span of sixteen pixels is
// z-tested and written with a few vector instructions: inverse depth (the z-buffer, 0 = empty —
// nearer is larger, so no division per pixel), the source depth and the source coordinates. The
// first thread's target writes the field's planes directly (its z-buffer, kept by the warper,
// becomes the field's depth in Finalise), so a view warped on one thread is never copied.
struct Target {
  float* inv_z;
  float* source_depth;  // null: not asked for (WarpOptions::compute_source_depth)
  float* uv;            // (u, v) interleaved, as WarpField::map
  int width, height;
};

// z-test and write of one pixel.
inline void WritePixel(const Target& t, std::size_t j, float iz, float zs, float u, float v) {
  if (iz <= t.inv_z[j]) return;  // z-test on inverse depth
  t.inv_z[j] = iz;
  if (t.source_depth) t.source_depth[j] = zs;
  t.uv[2 * j] = u;
  t.uv[2 * j + 1] = v;
}

// Rasterises one triangle with vertices a, b, c (source pixel coordinates sa, sb, sc) into the
// pixels [x0, x1] × [y0, y1] (already clipped to the image). Pixel centres at integer
// coordinates; 1/z and the source coordinates are interpolated linearly on screen.
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
      const float iz = wa * a.inv_z + wb * b.inv_z + wc * c.inv_z;
      const std::size_t j = std::size_t(y) * t.width + x;
      if (iz <= t.inv_z[j]) continue;  // z-test first: most pixels fail it or are outside
      const cv::Vec2f s = wa * sa + wb * sb + wc * sc;
      WritePixel(t, j, iz, wa * a.source_depth + wb * b.source_depth + wc * c.source_depth, s[0],
                 s[1]);
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
// virtual camera centre (origin) and to the source camera centre (in virtual coordinates), into
// `cos_angle` (reused frame to frame: fresh images cost page faults). In float with one square
// root per pixel, in a loop the compiler vectorises.
void ViewAngles(const cv::Mat& depth, const core::PinholeCamera& cam, const Eigen::Vector3d& source,
                cv::Mat& cos_angle) {
  cos_angle.create(depth.size(), CV_32FC1);
  const float cx = float(source.x()), cy = float(source.y()), cz = float(source.z());
  const float ifx = float(1.0 / cam.fx), ify = float(1.0 / cam.fy);
  const float ox = float(cam.cx), oy = float(cam.cy);
  for (int y = 0; y < depth.rows; ++y) {
    const float* z = depth.ptr<float>(y);
    float* out = cos_angle.ptr<float>(y);
    const float ry = (float(y) - oy) * ify;
    for (int x = 0; x < depth.cols; ++x) {
      const float rx = (float(x) - ox) * ifx;
      const float px = z[x] * rx, py = z[x] * ry, pz = z[x];  // the surface point
      const float qx = px - cx, qy = py - cy, qz = pz - cz;   // … seen from the source
      const float dot = px * qx + py * qy + pz * qz;
      const float norms = (px * px + py * py + pz * pz) * (qx * qx + qy * qy + qz * qz);
      out[x] = z[x] > 0.0f ? dot / std::sqrt(norms) : 0.0f;
    }
  }
}

// The general case: one quad (source pixels (u, r)…(u+1, r+1)) as two triangles.
void RasteriseQuad(const Vertices& v, int w, int u, int r, float max_ratio, const Target& t) {
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
    Rasterise(p00, p10, p11, s00, s10, s11, x0, x1, y0, y1, t);
  }
  if (Usable(p00, p11, p01, max_ratio)) {
    Rasterise(p00, p11, p01, s00, s11, s01, x0, x1, y0, y1, t);
  }
}

// A quad's geometry per lane (sixteen quads, or one quad broadcast): p00, the edge vectors to
// p10, p11 and p01, the inverse areas of triangles A = (p00, p10, p11) and B = (p00, p11, p01),
// 1/z and source depth at the corners, and whether each triangle may be drawn.
struct QuadLanes {
  F16 x00, y00, ax, ay, dx, dy, bx, by, inv_a, inv_b;
  F16 i00, i10, i01, i11, z00, z10, z01, z11;
  I16 ok_a, ok_b;
};

// The corners' screen positions and data (p00, p10, p01, p11) → QuadLanes; `draw` masks lanes.
inline QuadLanes MakeQuadLanes(const F16 (&x)[4], const F16 (&y)[4], const F16 (&iz)[4],
                               const F16 (&z)[4], I16 draw, float max_ratio) {
  QuadLanes q;
  const F16 zero = F16{}, tiny = zero + 1e-12f, ratio = zero + max_ratio;
  q.x00 = x[0];
  q.y00 = y[0];
  q.ax = x[1] - x[0], q.ay = y[1] - y[0];  // p10 − p00
  q.dx = x[3] - x[0], q.dy = y[3] - y[0];  // p11 − p00
  q.bx = x[2] - x[0], q.by = y[2] - y[0];  // p01 − p00
  const F16 area_a = q.ax * q.dy - q.ay * q.dx, area_b = q.dx * q.by - q.dy * q.bx;
  q.inv_a = (zero + 1.0f) / area_a;
  q.inv_b = (zero + 1.0f) / area_b;
  q.i00 = iz[0], q.i10 = iz[1], q.i01 = iz[2], q.i11 = iz[3];
  q.z00 = z[0], q.z10 = z[1], q.z01 = z[2], q.z11 = z[3];
  // As Usable: every vertex usable, no depth discontinuity; and a non-degenerate triangle.
  const I16 corners = (q.i00 != zero) & (q.i11 != zero);
  q.ok_a = draw & corners & (q.i10 != zero) & ((area_a >= tiny) | (area_a <= -tiny)) &
           (Max(q.z00, Max(q.z10, q.z11)) <= Min(q.z00, Min(q.z10, q.z11)) * ratio);
  q.ok_b = draw & corners & (q.i01 != zero) & ((area_b >= tiny) | (area_b <= -tiny)) &
           (Max(q.z00, Max(q.z11, q.z01)) <= Min(q.z00, Min(q.z11, q.z01)) * ratio);
  return q;
}

// The surface at pixel centres (px, py), one per lane, as Rasterise computes it: hit (inside A or
// B, and in_box), 1/z, source depth, and the source offsets from the quad's corner p00.
struct LaneHits {
  I16 hit;
  F16 iz, zs, su, sv;
};

inline LaneHits Evaluate(const QuadLanes& q, F16 px, F16 py, I16 in_box) {
  const F16 eps = F16{} - 1e-5f, one = F16{} + 1.0f;
  const F16 qx = px - q.x00, qy = py - q.y00;
  // Weights of each triangle's 2nd and 3rd vertex (edge functions), the 1st gets the rest.
  const F16 wb_a = (qx * q.dy - qy * q.dx) * q.inv_a, wc_a = (q.ax * qy - q.ay * qx) * q.inv_a;
  const F16 wb_b = (qx * q.by - qy * q.bx) * q.inv_b, wc_b = (q.dx * qy - q.dy * qx) * q.inv_b;
  const F16 wa_a = one - wb_a - wc_a, wa_b = one - wb_b - wc_b;
  const I16 in_a = in_box & q.ok_a & (wa_a >= eps) & (wb_a >= eps) & (wc_a >= eps);
  const I16 in_b = in_box & q.ok_b & (wa_b >= eps) & (wb_b >= eps) & (wc_b >= eps);
  const F16 wa = in_a ? wa_a : wa_b, wb = in_a ? wb_a : wb_b, wc = in_a ? wc_a : wc_b;
  LaneHits h;
  h.hit = in_a | in_b;
  h.iz = wa * q.i00 + wb * (in_a ? q.i10 : q.i11) + wc * (in_a ? q.i11 : q.i01);
  h.zs = wa * q.z00 + wb * (in_a ? q.z10 : q.z11) + wc * (in_a ? q.z11 : q.z01);
  h.su = in_a ? wb + wc : wb;  // A: (1,0),(1,1); B: (1,1),(0,1)
  h.sv = in_a ? wc : wb + wc;
  return h;
}

// z-test and write of one lane's hit at texel j; (su, sv) offsets from source pixel (u, r).
inline void Write(const LaneHits& h, int k, std::size_t j, float u, float r, const Target& t) {
  WritePixel(t, j, h.iz[k], h.zs[k], u + h.su[k], r + h.sv[k]);
}

// One quad whose box holds more than 2×2 pixel centres (magnified, or stretched): the box in
// tiles of 4×4 pixels, each tile one 16-lane evaluation.
void RasteriseQuadTiled(const Vertices& v, int w, int u, int r, float max_ratio, const Target& t,
                        int x0, int x1, int y0, int y1) {
  const std::size_t i = std::size_t(r) * w + u;
  const std::size_t c[4] = {i, i + 1, i + w, i + w + 1};  // p00, p10, p01, p11
  F16 x[4], y[4], iz[4], z[4];
  for (int n = 0; n < 4; ++n) {
    x[n] = F16{} + v.x[c[n]];
    y[n] = F16{} + v.y[c[n]];
    iz[n] = F16{} + v.inv_z[c[n]];
    z[n] = F16{} + v.source_depth[c[n]];
  }
  const QuadLanes q = MakeQuadLanes(x, y, iz, z, I16{} - 1, max_ratio);
  if (!q.ok_a[0] && !q.ok_b[0]) return;
  F16 ox, oy;
  for (int k = 0; k < kLanes; ++k) ox[k] = float(k & 3), oy[k] = float(k >> 2);
  for (int ty = y0; ty <= y1; ty += 4) {
    for (int tx = x0; tx <= x1; tx += 4) {
      const F16 px = ox + float(tx), py = oy + float(ty);
      const LaneHits h = Evaluate(q, px, py, (px <= float(x1)) & (py <= float(y1)));
      for (int k = 0; k < kLanes; ++k) {
        if (!h.hit[k]) continue;
        Write(h, k, std::size_t(ty + (k >> 2)) * t.width + std::size_t(tx + (k & 3)), float(u),
              float(r), t);
      }
    }
  }
}

// Sixteen quads of one row at a time. Between views of similar resolution nearly every quad's
// pixel-centre bounding box holds at most 2×2 pixel centres; for those lanes the four candidate
// pixels are decided with SIMD arithmetic — the same formulas as Rasterise — and only the z-test
// and write are scalar. Lanes whose box holds more pixels go through RasteriseQuadTiled.
void RasteriseRowVectorised(const Vertices& v, int w, int r, float max_ratio, const Target& t) {
  const std::size_t base = std::size_t(r) * w;
  const F16 zero = F16{}, one = zero + 1.0f;
  const F16 x_max = zero + float(t.width - 1), y_max = zero + float(t.height - 1);
  const F16 lo = zero - 1e6f, hi = zero + 1e6f;
  const F16 lane = core::lanes::Iota();
  // Quads u … w−2; the last group's lanes past w−2 are masked (the vertex arrays are padded).
  // Each group starts at a quad drawn on its own: the quads that planar blocks leave to be drawn
  // (their edges towards a non-planar neighbour, and the neighbour) then share groups, where
  // groups aligned to sixteen held a block's edge quad alone in half the cases.
  for (int u = 0; u + 1 < w; u += kLanes) {
    I16 skip = core::lanes::LoadBytes(&v.skip[base + u]);
    const unsigned drawn = core::lanes::Bits(skip == 0);
    if (!drawn) continue;  // sixteen quads inside planar blocks
    if (const int first = __builtin_ctz(drawn); first > 0) {
      u += first;
      skip = core::lanes::LoadBytes(&v.skip[base + u]);
    }
    const std::size_t i = base + u;
    const std::size_t c[4] = {i, i + 1, i + w, i + w + 1};  // p00, p10, p01, p11
    F16 x[4], y[4], iz[4];
    I16 ok[4];
    for (int n = 0; n < 4; ++n) {
      x[n] = Load(&v.x[c[n]]);
      y[n] = Load(&v.y[c[n]]);
      iz[n] = Load(&v.inv_z[c[n]]);
      ok[n] = iz[n] != zero;
    }
    ok[0] &= (lane + float(u) < float(w - 1)) & (skip == 0);
    // The box; an unusable vertex takes p00's place (its triangles are not drawn).
    F16 bx[4] = {x[0]}, by[4] = {y[0]};
    for (int n = 1; n < 4; ++n) {
      bx[n] = ok[n] ? x[n] : x[0];
      by[n] = ok[n] ? y[n] : y[0];
    }
    const F16 qx0 = Max(Ceil(Max(Min(Min(bx[0], bx[1]), Min(bx[2], bx[3])), lo)), zero);
    const F16 qx1 = Min(Floor(Min(Max(Max(bx[0], bx[1]), Max(bx[2], bx[3])), hi)), x_max);
    const F16 qy0 = Max(Ceil(Max(Min(Min(by[0], by[1]), Min(by[2], by[3])), lo)), zero);
    const F16 qy1 = Min(Floor(Min(Max(Max(by[0], by[1]), Max(by[2], by[3])), hi)), y_max);
    const F16 nx = qx1 - qx0 + one, ny = qy1 - qy0 + one;
    const I16 any = ok[0] & ok[3] & (ok[1] | ok[2]) & (nx >= one) & (ny >= one);
    const I16 small = any & (nx <= one + one) & (ny <= one + one);
    if (!core::lanes::Any(any)) continue;
    F16 z[4];
    for (int n = 0; n < 4; ++n) z[n] = Load(&v.source_depth[c[n]]);
    const QuadLanes q = MakeQuadLanes(x, y, iz, z, small, max_ratio);
    LaneHits hits[4];
    for (int n = 0; n < 4; ++n) {
      const float ox = float(n & 1), oy = float(n >> 1);
      hits[n] = Evaluate(q, qx0 + ox, qy0 + oy, (zero + ox < nx) & (zero + oy < ny));
    }
    for (unsigned big = core::lanes::Bits(any & ~small); big; big &= big - 1) {
      const int k = __builtin_ctz(big);
      RasteriseQuadTiled(v, w, u + k, r, max_ratio, t, int(qx0[k]), int(qx1[k]), int(qy0[k]),
                         int(qy1[k]));
    }
    // The small quads' hits, candidate pixel by candidate pixel: only hits are visited.
    const I16 j0 = core::lanes::AsInt(small ? qy0 : zero) * t.width +  // (other lanes' boxes
                   core::lanes::AsInt(small ? qx0 : zero);             // may lie far outside)
    for (int n = 0; n < 4; ++n) {
      const std::size_t step = std::size_t(n >> 1) * t.width + std::size_t(n & 1);
      for (unsigned hit = core::lanes::Bits(hits[n].hit); hit; hit &= hit - 1) {
        const int k = __builtin_ctz(hit);
        Write(hits[n], k, std::size_t(j0[k]) + step, float(u + k), float(r), t);
      }
    }
  }
}

// A planar block or run of blocks (top-left vertex, width × height quads), drawn as the convex
// quadrilateral between its corners, row span by row span. On a plane 1/z is affine on screen,
// and so is A/z for any A linear in 3-D: the source depth z_s and z_s·u_s, z_s·v_s
// (u_s = (fx·X_s + cx·Z_s)/Z_s). Interpolating those and dividing gives exact source coordinates
// across the block, where interpolating u_s itself would bend straight texture lines. A block
// with a corner behind the near plane, or seen edge-on (not convex on screen), is drawn quad by
// quad instead.
// A block's corners on screen in order around it (p00, p10, p11, p01) with their attributes
// 1/z, z_s/z, z_s·u_s/z, z_s·v_s/z, and whether the block can be drawn as one polygon: every
// corner in front of the near plane, and convex with some area on screen.
struct BlockCorners {
  float x[4], y[4], attr[4][4];
  bool usable = true;
};

BlockCorners CornersOf(const Vertices& v, int w, const cv::Rect& block) {
  const int u0 = block.x, r0 = block.y, u1 = u0 + block.width, r1 = r0 + block.height;
  const std::size_t i = std::size_t(r0) * w + u0, down = std::size_t(block.height) * w;
  const std::size_t c[4] = {i, i + block.width, i + down + block.width, i + down};
  const float cu[4] = {float(u0), float(u1), float(u1), float(u0)};
  const float cr[4] = {float(r0), float(r0), float(r1), float(r1)};
  BlockCorners k;
  for (int n = 0; n < 4; ++n) {
    k.x[n] = v.x[c[n]], k.y[n] = v.y[c[n]];
    k.attr[0][n] = v.inv_z[c[n]];
    k.attr[1][n] = k.attr[0][n] * v.source_depth[c[n]];
    k.attr[2][n] = k.attr[1][n] * cu[n];
    k.attr[3][n] = k.attr[1][n] * cr[n];
    k.usable &= k.attr[0][n] != 0.0f;
  }
  float turn = 0.0f;  // the corners must turn one way (convex) and span an area
  for (int n = 0; n < 4 && k.usable; ++n) {
    const int a = (n + 1) % 4, b = (n + 2) % 4;
    const float cross =
        (k.x[a] - k.x[n]) * (k.y[b] - k.y[a]) - (k.y[a] - k.y[n]) * (k.x[b] - k.x[a]);
    k.usable = std::abs(cross) > 1e-3f && (n == 0 || (cross > 0) == (turn > 0));
    turn = cross;
  }
  return k;
}

void RasteriseBlock(const Vertices& v, int w, const cv::Rect& block, float max_ratio,
                    const Target& t) {
  const BlockCorners corners = CornersOf(v, w, block);
  if (!corners.usable) {  // (its vertices were all projected: WarpWith)
    for (int r = block.y; r < block.y + block.height; ++r)
      for (int u = block.x; u < block.x + block.width; ++u) RasteriseQuad(v, w, u, r, max_ratio, t);
    return;
  }
  const float(&x)[4] = corners.x;
  const float(&y)[4] = corners.y;
  const float(&attr)[4][4] = corners.attr;
  // Gradients of each attribute on screen from p00, p10 and p01 (one plane).
  const float e1x = x[1] - x[0], e1y = y[1] - y[0], e2x = x[3] - x[0], e2y = y[3] - y[0];
  const float inv_det = 1.0f / (e1x * e2y - e1y * e2x);
  float gx[4], gy[4];  // attribute k at (px, py) = attr[k][0] + gx·(px − x0) + gy·(py − y0)
  for (int k = 0; k < 4; ++k) {
    const float d1 = attr[k][1] - attr[k][0], d2 = attr[k][3] - attr[k][0];
    gx[k] = (d1 * e2y - d2 * e1y) * inv_det;
    gy[k] = (e1x * d2 - e2x * d1) * inv_det;
  }
  const int y0 = std::max(0, int(std::ceil(*std::min_element(y, y + 4))));
  const int y1 = std::min(t.height - 1, int(std::floor(*std::max_element(y, y + 4))));
  constexpr float kEdge = 1e-4f;  // pixel centres on an edge belong to both neighbours
  // Each row's span is where it crosses the edges: the block is convex, so the span starts at the
  // rightmost crossing of its left edges and ends at the leftmost of its right edges. Per edge the
  // crossing's step per row (no division per row) and its side (that of the block's centre).
  float slope[4], left[4];
  const float mx = 0.25f * (x[0] + x[1] + x[2] + x[3]), my = 0.25f * (y[0] + y[1] + y[2] + y[3]);
  for (int n = 0; n < 4; ++n) {
    const int m = (n + 1) % 4;
    slope[n] = y[m] == y[n] ? 0.0f : (x[m] - x[n]) / (y[m] - y[n]);
    left[n] = y[m] == y[n] ? -1.0f : float(x[n] + (my - y[n]) * slope[n] < mx);  // −1: level
  }
  const F16 lane = core::lanes::Iota();
  for (int py = y0; py <= y1; ++py) {
    const float fy = float(py);
    float xl = -1e30f, xr = 1e30f;
    for (int n = 0; n < 4; ++n) {
      const float ex = x[n] + (fy - y[n]) * slope[n];
      if (left[n] > 0.5f) xl = std::max(xl, ex);
      if (left[n] == 0.0f) xr = std::min(xr, ex);
    }
    const int px0 = std::max(0, int(std::ceil(xl - kEdge)));
    const int px1 = std::min(t.width - 1, int(std::floor(xr + kEdge)));
    const std::size_t row = std::size_t(py) * t.width;
    F16 at_row[4];
    for (int k = 0; k < 4; ++k) at_row[k] = F16{} + (attr[k][0] + gy[k] * (fy - y[0]));
    // Sixteen pixels of the span at a time, z-test and write included (masked: the span's end
    // and the pixels that hold a nearer surface are left alone).
    for (int px = px0; px <= px1; px += kLanes) {
      const F16 fx = lane + (float(px) - x[0]);
      const F16 iz = at_row[0] + gx[0] * fx, a = at_row[1] + gx[1] * fx;
      const F16 inv_a = Reciprocal(a);
      const F16 us = (at_row[2] + gx[2] * fx) * inv_a, vs = (at_row[3] + gx[3] * fx) * inv_a;
      const std::size_t j = row + std::size_t(px);
      const I16 in_span = lane < float(px1 - px + 1);
      const I16 nearer = in_span & (iz > LoadMasked(t.inv_z + j, in_span));
      StoreMasked(t.inv_z + j, iz, nearer);
      if (t.source_depth) StoreMasked(t.source_depth + j, a * Reciprocal(iz), nearer);
      StoreMaskedPairs(t.uv + 2 * j, us, vs, nearer);
    }
  }
}

}  // namespace

MeshPlan MeshPlanFor(const cv::Mat& depth, const WarpOptions& options) {
  return PlanMesh(depth, options.planar_block, options.planar_tolerance);
}

// The buffers of a target other than the field (threads after the first of a split view).
struct TargetBuffers {
  std::vector<float> inv_z, source_depth, uv;
  Target Clear(int width, int height, bool with_source_depth) {
    const std::size_t n = std::size_t(width) * height;
    inv_z.assign(n, 0.0f);
    source_depth.resize(with_source_depth ? n : 0);
    uv.resize(2 * n);
    return {inv_z.data(), with_source_depth ? source_depth.data() : nullptr, uv.data(), width,
            height};
  }
};

struct DepthMeshWarper::Scratch {
  Vertices vertices;
  // The first target's z-buffer (inverse depth): all zeros between warps — Finalise clears what
  // it reads — so no warp clears it whole, and it stays in the cache of the core that warps.
  std::vector<float> zbuffer;
  bool zbuffer_dirty = false;        // a warp stopped between drawing and Finalise
  std::vector<TargetBuffers> extra;  // threads 1… of a view split between threads
  MeshPlan plan;                     // the plan of a view warped without a fitting one
};

namespace {

// The first target: the scratch's z-buffer (cleared whole only after a warp that did not finish)
// and the field's planes (its depth, if asked, is written by Finalise).
Target FieldTarget(WarpField& field, std::vector<float>& zbuffer, bool& zbuffer_dirty, int width,
                   int height, const WarpOptions& o) {
  const std::size_t n = std::size_t(width) * height;
  if (zbuffer.size() != n || zbuffer_dirty) zbuffer.assign(n, 0.0f);
  zbuffer_dirty = true;
  field.map.create(height, width, CV_32FC2);
  if (o.compute_depth) {
    field.depth.create(height, width, CV_32FC1);
  } else {
    field.depth.release();
  }
  const bool with_source_depth = o.compute_source_depth;
  if (with_source_depth) {
    field.source_depth.create(height, width, CV_32FC1);
  } else {
    field.source_depth.release();
  }
  return {zbuffer.data(), with_source_depth ? field.source_depth.ptr<float>() : nullptr,
          field.map.ptr<float>(), width, height};
}

// Per virtual pixel, the nearest surface of the other targets into the first, sixteen pixels
// at a time.
void Merge(const std::vector<Target>& targets, int threads) {
  const Target& t = targets[0];
  ParallelBlocks(t.height, threads, [&](int y0, int y1) {
    const std::size_t end = std::size_t(y1) * t.width;
    for (std::size_t j = std::size_t(y0) * t.width; j < end; j += kLanes) {
      const I16 in_rows = core::lanes::Iota() < float(end - j);
      for (std::size_t k = 1; k < targets.size(); ++k) {
        const Target& o = targets[k];
        const F16 iz = LoadMasked(o.inv_z + j, in_rows);
        const I16 nearer = in_rows & (iz > LoadMasked(t.inv_z + j, in_rows));
        if (!core::lanes::Any(nearer)) continue;
        StoreMasked(t.inv_z + j, iz, nearer);
        if (t.source_depth) {
          StoreMasked(t.source_depth + j, LoadMasked(o.source_depth + j, nearer), nearer);
        }
        F16 u, v;
        core::lanes::LoadMaskedPairs(o.uv + 2 * j, nearer, u, v);
        StoreMaskedPairs(t.uv + 2 * j, u, v, nearer);
      }
    }
  });
}

// The z-buffer becomes `depth` if asked (0 where uncovered, not 1/0) and is cleared again;
// uncovered pixels get the field's markers (map −1, source depth 0). Returns the covered pixels.
int Finalise(const Target& t, float* depth, int threads) {
  std::vector<int> covered(std::size_t(t.height), 0);
  ParallelBlocks(t.height, threads, [&](int y0, int y1) {
    const F16 zero{};
    for (int y = y0; y < y1; ++y) {
      const std::size_t row = std::size_t(y) * t.width;
      int n = 0;
      for (int x = 0; x < t.width; x += kLanes) {
        const std::size_t j = row + std::size_t(x);
        const I16 in_row = core::lanes::Iota() < float(t.width - x);
        const F16 iz = LoadMasked(t.inv_z + j, in_row);
        const I16 hit = iz > zero, miss = in_row & ~hit;
        if (depth) StoreMasked(depth + j, hit ? Reciprocal(iz) : zero, in_row);
        StoreMasked(t.inv_z + j, zero, hit);  // the z-buffer clean for the next warp
        if (t.source_depth) StoreMasked(t.source_depth + j, zero, miss);
        StoreMaskedPairs(t.uv + 2 * j, zero - 1.0f, zero - 1.0f, miss);
        n += core::lanes::Count(hit);
      }
      covered[std::size_t(y)] = n;
    }
  });
  int total = 0;
  for (int n : covered) total += n;
  return total;
}

}  // namespace

DepthMeshWarper::DepthMeshWarper(const WarpOptions& options)
    : options_(options), scratch_(std::make_unique<Scratch>()) {}
DepthMeshWarper::~DepthMeshWarper() = default;

void DepthMeshWarper::Warp(const core::PinholeCamera& src, const Eigen::Isometry3d& T_world_src,
                           const cv::Mat& depth, const core::PinholeCamera& dst,
                           const Eigen::Isometry3d& T_world_dst, WarpField& field) {
  WarpWith(*scratch_, ThreadCount(options_.threads), src, T_world_src, depth, nullptr, dst,
           T_world_dst, field);
}

void DepthMeshWarper::WarpMany(const std::vector<SourceView>& sources,
                               const core::PinholeCamera& dst, const Eigen::Isometry3d& T_world_dst,
                               std::vector<WarpField>& fields) {
  fields.resize(sources.size());
  const int threads = ThreadCount(options_.threads);
  if (threads < 2 || sources.size() < 2) {
    for (std::size_t k = 0; k < sources.size(); ++k) {
      WarpWith(*scratch_, threads, *sources[k].camera, *sources[k].T_world_cam, *sources[k].depth,
               sources[k].plan, dst, T_world_dst, fields[k]);
    }
    return;
  }
  // Whole views per thread: no thread waits for another or merges its z-buffer. Each takes the
  // next view not yet taken, so a thread that drew cheap views draws more of them. (Splitting the
  // view left over — seven on two cores — between the threads instead was no faster: the
  // merge and the extra synchronisation cost what the idle core loses.)
  const int workers = std::min(threads, int(sources.size()));
  std::atomic<std::size_t> next{0};
  while (int(worker_scratch_.size()) < workers) {
    worker_scratch_.push_back(std::make_unique<Scratch>());
  }
  std::vector<std::string> errors(static_cast<std::size_t>(workers));
  ParallelBlocks(workers, workers, [&](int w0, int w1) {
    for (int w = w0; w < w1; ++w) {
      try {
        for (std::size_t k = next++; k < sources.size(); k = next++) {
          WarpWith(*worker_scratch_[std::size_t(w)], 1, *sources[k].camera, *sources[k].T_world_cam,
                   *sources[k].depth, sources[k].plan, dst, T_world_dst, fields[k]);
        }
      } catch (const std::exception& e) {
        errors[std::size_t(w)] = e.what();  // rethrown below, not across the thread pool
      }
    }
  });
  for (const std::string& e : errors) {
    if (!e.empty()) throw std::invalid_argument(e);
  }
}

void DepthMeshWarper::WarpWith(Scratch& scratch, int threads, const core::PinholeCamera& src,
                               const Eigen::Isometry3d& T_world_src, const cv::Mat& depth,
                               const MeshPlan* kept_plan, const core::PinholeCamera& dst,
                               const Eigen::Isometry3d& T_world_dst, WarpField& field) const {
  const WarpOptions& o = options_;
  src.Check();
  dst.Check();
  if (!core::IsRigid(T_world_src) || !core::IsRigid(T_world_dst)) {
    throw std::invalid_argument("WarpView: a camera pose is not a rigid transform");
  }
  if (o.compute_view_angles && !o.compute_depth) {
    throw std::invalid_argument("WarpView: compute_view_angles needs compute_depth");
  }
  if (depth.type() != CV_32FC1 || depth.cols != src.width || depth.rows != src.height) {
    throw std::invalid_argument(
        "WarpView: source depth must be CV_32FC1 of the source camera's "
        "size " +
        std::to_string(src.width) + "x" + std::to_string(src.height));
  }
  const Eigen::Isometry3d T_vs = T_world_dst.inverse() * T_world_src;
  Vertices& v = scratch.vertices;
  v.Resize(std::size_t(src.width) * src.height);
  // The caller's plan if it was made for these options (else planned anew).
  const bool kept = kept_plan && kept_plan->Fits(depth.size(), o.planar_block, o.planar_tolerance);
  if (!kept) scratch.plan = MeshPlanFor(depth, o);
  const MeshPlan& plan = kept ? *kept_plan : scratch.plan;
  v.skip = plan.skip.data();
  const std::vector<cv::Rect>& blocks = plan.runs;
  // Only the vertices something draws from: block rows (the runs' corners) whole, other rows where
  // a quad is drawn on its own; a run that cannot be one polygon is drawn quad by quad, so its
  // rows are projected whole as well.
  const VertexProjector project(src, T_vs, depth, dst, o.near_plane, v);
  const int block_size = std::max(1, o.planar_block);
  ParallelBlocks(src.height, threads, [&](int r0, int r1) {
    for (int r = r0; r < r1; ++r)
      project.Row(r, !blocks.empty() && (r % block_size == 0 || r == src.height - 1));
  });
  for (const cv::Rect& b : blocks) {
    if (CornersOf(v, src.width, b).usable) continue;
    for (int r = b.y + 1; r < b.y + b.height; ++r) project.Row(r, true);
  }

  // Threads take blocks of source rows, each with its own target, merged by depth afterwards.
  const int n_threads = std::max(1, std::min(src.height - 1, threads));
  scratch.extra.resize(std::size_t(n_threads - 1));
  std::vector<Target> targets = {
      FieldTarget(field, scratch.zbuffer, scratch.zbuffer_dirty, dst.width, dst.height, o)};
  for (TargetBuffers& b : scratch.extra) {
    targets.push_back(b.Clear(dst.width, dst.height, o.compute_source_depth));
  }
  const float max_ratio = float(1.0 + o.max_relative_depth_jump);
  const int w = src.width;
  ParallelBlocks(n_threads, n_threads, [&](int t0, int t1) {
    for (int ti = t0; ti < t1; ++ti) {
      const Target& view = targets[std::size_t(ti)];
      const int r_begin = (src.height - 1) * ti / n_threads;
      const int r_end = (src.height - 1) * (ti + 1) / n_threads;
      for (const cv::Rect& b : blocks) {
        if (b.y >= r_begin && b.y < r_end) RasteriseBlock(v, w, b, max_ratio, view);
      }
      for (int r = r_begin; r < r_end; ++r) {
        if (o.vectorised) {
          RasteriseRowVectorised(v, w, r, max_ratio, view);
        } else {
          for (int u = 0; u + 1 < w; ++u) {
            if (v.skip[std::size_t(r) * w + u] == 0) RasteriseQuad(v, w, u, r, max_ratio, view);
          }
        }
      }
    }
  });
  if (n_threads > 1) Merge(targets, threads);
  field.covered =
      Finalise(targets[0], o.compute_depth ? field.depth.ptr<float>() : nullptr, threads);
  scratch.zbuffer_dirty = false;
  if (o.compute_view_angles) ViewAngles(field.depth, dst, T_vs.translation(), field.cos_angle);
}

WarpField WarpView(const core::PinholeCamera& source_camera,
                   const Eigen::Isometry3d& T_world_source, const cv::Mat& source_depth,
                   const core::PinholeCamera& virtual_camera,
                   const Eigen::Isometry3d& T_world_virtual, const WarpOptions& options) {
  WarpField field;
  DepthMeshWarper(options).Warp(source_camera, T_world_source, source_depth, virtual_camera,
                                T_world_virtual, field);
  return field;
}

}  // namespace novelty::views
