#include "eval/memory_plateau.h"

namespace novelty::eval {

MemoryPlateau FindMemoryPlateau(const std::vector<SoakSample>& samples) {
  MemoryPlateau p;
  if (samples.size() < 2) return p;
  std::size_t start = 0;
  for (std::size_t i = 1; i < samples.size(); ++i)
    if (samples[i].views != samples[i - 1].views) start = i;
  if (start + 1 >= samples.size()) return p;  // still growing at the end
  p.reached = true;
  p.frame = samples[start].frame;
  p.start_mb = samples[start].resident_mb;
  p.end_mb = samples.back().resident_mb;
  p.growth = (p.end_mb - p.start_mb) / p.start_mb;
  return p;
}

}  // namespace novelty::eval
