#include "maps/views/block_rasteriser.h"

#include <algorithm>
#include <cmath>

#include "maps/views/quad_rasteriser.h"

namespace novelty::views::mesh {

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

}  // namespace novelty::views::mesh
