// Attentional selectivity of a surprise (or difference) map for a region of interest (4.3.2):
//   AS  = 10 log10( mean of the region's block values / max block value outside )  (eq. 4.24)
//   PAS = 10 log10( max of the region's block values  / max block value outside )  (eq. 4.25)
// Block values are the means of 4×4 blocks. Blocks within `border_blocks` of the image border are
// left out (the thesis excludes them because predictions there often have no data; the width is
// not given — 2 blocks = 8 pixels is the default here). A block belongs to the region when all
// its pixels are in the mask and to the outside when none is; blocks on the region's border are
// neither, so the result does not depend on where the object falls in the block grid (counting
// them either way mixes the object's values with the background's). A region too small to hold
// a whole block is represented by its blocks at least half in the mask. NaN pixels (no
// prediction) are ignored in a block's mean and a block with no valid pixel is left out.
#pragma once

#include <opencv2/core.hpp>

namespace novelty::eval {

struct SelectivityOptions {
  int block_size = 4;     ///< thesis: 4×4 blocks
  int border_blocks = 2;  ///< blocks left out along each image border
};

struct Selectivity {
  double as_db = 0.0;   ///< eq. 4.24; NaN if the region or the outside has no block
  double pas_db = 0.0;  ///< eq. 4.25
  int region_blocks = 0;
  int outside_blocks = 0;
  int border_blocks = 0;  ///< blocks partly in the region: neither region nor outside
  /// Share of the evaluated pixels (all but the border) that have a value (not NaN): AS and PAS
  /// are measured over those, so report this beside them.
  double coverage = 0.0;
};

/// map: CV_32FC1 values ≥ 0; region: CV_8UC1 mask (non-zero = region) of the same size.
Selectivity AttentionalSelectivity(const cv::Mat& map, const cv::Mat& region,
                                   const SelectivityOptions& options = {});

}  // namespace novelty::eval
