// metrics.csv: per frame and changed region, the attentional selectivity of surprise and of
// differencing and the coverage it was measured over — what the findings are computed from.
#pragma once

#include <fstream>
#include <string>

#include "eval/selectivity_findings.h"

namespace novelty::eval {

class SelectivityCsv {
 public:
  /// Creates `path` with its header line; throws std::runtime_error naming it if it cannot.
  explicit SelectivityCsv(const std::string& path);
  /// One row: frame, phase, region, AS and PAS of surprise and of differencing (dB, blank where
  /// undefined), coverage.
  void Add(const SelectivityRow& row, const std::string& phase);

 private:
  std::string path_;
  std::ofstream out_;
};

}  // namespace novelty::eval
