// Test helper: a row of per-frame selectivity (AS and PAS of surprise and differencing, dB) for
// one region, as novelty-run's metrics.csv has them (coverage: the share of pixels they cover).
// Shared by the findings tests.
#pragma once

#include <string>

#include "eval/selectivity_findings.h"

namespace novelty::eval {

inline SelectivityRow Row(int frame, const std::string& region, double as_s, double pas_s,
                          double as_d, double pas_d, double coverage = 0.9) {
  SelectivityRow r;
  r.surprise.coverage = r.difference.coverage = coverage;
  r.frame = frame;
  r.region = region;
  r.surprise.as_db = as_s, r.surprise.pas_db = pas_s;
  r.difference.as_db = as_d, r.difference.pas_db = pas_d;
  return r;
}

}  // namespace novelty::eval
