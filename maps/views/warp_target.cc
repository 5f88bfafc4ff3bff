#include "maps/views/warp_target.h"

#include "core/lanes.h"

namespace novelty::views::mesh {

using namespace core::lanes;  // F16, I16, Load, Min… (core/lanes.h)

Target TargetBuffers::Clear(int width, int height, bool with_source_depth) {
  const std::size_t n = std::size_t(width) * height;
  inv_z.assign(n, 0.0f);
  source_depth.resize(with_source_depth ? n : 0);
  uv.resize(2 * n);
  return {inv_z.data(), with_source_depth ? source_depth.data() : nullptr, uv.data(), width,
          height};
}

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
        if (depth) StoreMasked(depth + j, Select(hit, Reciprocal(iz), zero), in_row);
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

}  // namespace novelty::views::mesh
