#include "maps/views/quad_rasteriser.h"

#include <algorithm>
#include <cmath>

namespace novelty::views::mesh {

namespace {

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
  const F16 wa = Select(in_a, wa_a, wa_b), wb = Select(in_a, wb_a, wb_b);
  const F16 wc = Select(in_a, wc_a, wc_b);
  LaneHits h;
  h.hit = in_a | in_b;
  h.iz = wa * q.i00 + wb * Select(in_a, q.i10, q.i11) + wc * Select(in_a, q.i11, q.i01);
  h.zs = wa * q.z00 + wb * Select(in_a, q.z10, q.z11) + wc * Select(in_a, q.z11, q.z01);
  h.su = Select(in_a, wb + wc, wb);  // A: (1,0),(1,1); B: (1,1),(0,1)
  h.sv = Select(in_a, wc, wb + wc);
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

}  // namespace

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
      bx[n] = Select(ok[n], x[n], x[0]);
      by[n] = Select(ok[n], y[n], y[0]);
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
    const I16 j0 = core::lanes::AsInt(Select(small, qy0, zero)) * t.width +  // (other lanes' boxes
                   core::lanes::AsInt(Select(small, qx0, zero));             // may lie far outside)
    for (int n = 0; n < 4; ++n) {
      const std::size_t step = std::size_t(n >> 1) * t.width + std::size_t(n & 1);
      for (unsigned hit = core::lanes::Bits(hits[n].hit); hit; hit &= hit - 1) {
        const int k = __builtin_ctz(hit);
        Write(hits[n], k, std::size_t(j0[k]) + step, float(u + k), float(r), t);
      }
    }
  }
}

}  // namespace novelty::views::mesh
