// A matching-cost volume over a pixel grid: for every pixel, one cost per label (depth
// hypothesis), stored label-fastest so a pixel's costs are contiguous (what belief propagation's
// message updates walk along).
#pragma once

#include <vector>

namespace novelty::sensors {

struct CostVolume {
  int width = 0, height = 0, labels = 0;
  std::vector<float> cost;  ///< [(y·width + x)·labels + l]

  CostVolume() = default;
  CostVolume(int w, int h, int l, float fill = 0.0f)
      : width(w), height(h), labels(l), cost(size_t(w) * h * l, fill) {}
  float* at(int x, int y) { return cost.data() + (size_t(y) * width + x) * labels; }
  const float* at(int x, int y) const { return cost.data() + (size_t(y) * width + x) * labels; }
};

}  // namespace novelty::sensors
