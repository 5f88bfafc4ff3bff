// A matching-cost volume over a pixel grid: for every depth hypothesis (label) one cost image,
// stored label-major so the plane sweep writes each hypothesis's image contiguously.
#pragma once

#include <cstddef>
#include <vector>

namespace novelty::sensors {

struct CostVolume {
  int width = 0, height = 0, labels = 0;
  std::vector<float> cost;  ///< [(l·height + y)·width + x]

  CostVolume() = default;
  CostVolume(int w, int h, int l, float fill = 0.0f)
      : width(w), height(h), labels(l), cost(std::size_t(w) * h * l, fill) {}
  float& operator()(int x, int y, int l) { return cost[Index(x, y, l)]; }
  float operator()(int x, int y, int l) const { return cost[Index(x, y, l)]; }
  /// The cost image of label l (width × height, row-major).
  float* slice(int l) { return cost.data() + std::size_t(l) * width * height; }
  const float* slice(int l) const { return cost.data() + std::size_t(l) * width * height; }

 private:
  std::size_t Index(int x, int y, int l) const {
    return (std::size_t(l) * height + y) * width + x;
  }
};

}  // namespace novelty::sensors
