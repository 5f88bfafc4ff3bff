#include "eval/attentional_selectivity.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace novelty::eval {

Selectivity AttentionalSelectivity(const cv::Mat& map, const cv::Mat& region,
                                   const SelectivityOptions& o) {
  if (map.type() != CV_32FC1 || region.type() != CV_8UC1 || map.size() != region.size()) {
    throw std::invalid_argument(
        "AttentionalSelectivity: need a CV_32FC1 map and a CV_8UC1 mask "
        "of the same size");
  }
  const int b = o.block_size;
  const int bx = map.cols / b, by = map.rows / b;
  struct Block {
    double mean;
    int in_region;  // pixels of the block in the mask
  };
  std::vector<Block> blocks;
  long valid_pixels = 0, pixels = 0;
  for (int j = o.border_blocks; j < by - o.border_blocks; ++j) {
    for (int i = o.border_blocks; i < bx - o.border_blocks; ++i) {
      double sum = 0.0;
      int valid = 0, in_region = 0;
      for (int y = j * b; y < (j + 1) * b; ++y) {
        for (int x = i * b; x < (i + 1) * b; ++x) {
          const float v = map.at<float>(y, x);
          in_region += region.at<uint8_t>(y, x) != 0;
          if (std::isnan(v)) continue;
          sum += v;
          ++valid;
        }
      }
      valid_pixels += valid;
      pixels += b * b;
      if (valid > 0) blocks.push_back({sum / valid, in_region});
    }
  }
  const int whole = b * b;
  const bool has_whole_block = std::any_of(blocks.begin(), blocks.end(),
                                           [&](const Block& k) { return k.in_region == whole; });
  // The least share of a block in the mask that makes it a region block.
  const int least = has_whole_block ? whole : (whole + 1) / 2;
  double region_sum = 0.0, region_max = 0.0, outside_max = 0.0;
  Selectivity s;
  s.coverage = pixels > 0 ? double(valid_pixels) / double(pixels) : 0.0;
  for (const Block& k : blocks) {
    if (k.in_region >= least) {
      region_sum += k.mean;
      region_max = std::max(region_max, k.mean);
      ++s.region_blocks;
    } else if (k.in_region == 0) {
      outside_max = std::max(outside_max, k.mean);
      ++s.outside_blocks;
    } else {
      ++s.border_blocks;
    }
  }
  if (s.region_blocks == 0 || s.outside_blocks == 0) {
    s.as_db = s.pas_db = std::numeric_limits<double>::quiet_NaN();
    return s;
  }
  s.as_db = 10.0 * std::log10((region_sum / s.region_blocks) / outside_max);  // eq. 4.24
  s.pas_db = 10.0 * std::log10(region_max / outside_max);                     // eq. 4.25
  return s;
}

}  // namespace novelty::eval
