// Whether a long run's memory stays flat once its map has stopped growing (the soak of
// apps/novelty_soak.cc): the plateau begins at the first sample after the map's last new view.
#pragma once

#include <vector>

namespace novelty::eval {

struct SoakSample {
  int frame = 0;
  double resident_mb = 0.0;
  int views = 0;  ///< reference views in the map
};

struct MemoryPlateau {
  bool reached = false;      ///< the map stopped growing before the last sample
  int frame = 0;             ///< where the plateau begins
  double start_mb = 0.0;     ///< resident memory there
  double end_mb = 0.0;       ///< at the last sample
  double growth = 0.0;       ///< (end − start) / start
};

/// Samples in frame order. Not reached if the view count changes at the last sample or there
/// are fewer than two samples.
MemoryPlateau FindMemoryPlateau(const std::vector<SoakSample>& samples);

}  // namespace novelty::eval
