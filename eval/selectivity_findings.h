// The findings of thesis 4.3 read from per-frame attentional selectivity: mean AS and PAS of
// Bayesian surprise and of image differencing for one region over a range of frames, and whether
// a stated finding holds there.
#pragma once

#include <string>
#include <vector>

#include "eval/attentional_selectivity.h"

namespace novelty::eval {

/// One changed region in one frame (a row of novelty-run's metrics.csv).
struct SelectivityRow {
  int frame = 0;
  std::string region;
  Selectivity surprise, difference;
};

/// Means over the frames where both measures are finite.
struct MeanSelectivity {
  int frames = 0;
  double as_surprise = 0, pas_surprise = 0, as_difference = 0, pas_difference = 0;
  double coverage = 0;  ///< mean share of the surprise map's evaluated pixels with a value
};

MeanSelectivity MeanOver(const std::vector<SelectivityRow>& rows, const std::string& region,
                         int first, int last);

/// What a finding claims about the means.
enum class Claim {
  kSurpriseMoreSelective,  ///< AS surprise > AS differencing (the glass, fig. 4.9)
  kBothDetect,             ///< PAS > 0 dB for both: each puts its peak on the region (fig. 4.12)
  kSurpriseLessSelective,  ///< AS surprise < AS differencing (the removed cup, phase D)
};

struct Finding {
  std::string what;  ///< the thesis's statement, e.g. "glass: surprise higher AS (fig. 4.9)"
  std::string region;
  Claim claim = Claim::kSurpriseMoreSelective;
  int first = 0, last = 0;  ///< frames read
};

struct FindingResult {
  MeanSelectivity mean;
  bool holds = false;  ///< false when no frame in range shows the region
};

FindingResult Evaluate(const std::vector<SelectivityRow>& rows, const Finding& finding);

/// Fig. 4.13: with sparser reference views surprise keeps more of its peak selectivity — its PAS
/// falls less than differencing's from `full` to `sparse` (false when either has no frame).
bool SurpriseLosesLess(const MeanSelectivity& full, const MeanSelectivity& sparse);

}  // namespace novelty::eval
