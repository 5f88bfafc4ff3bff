#include "eval/selectivity_findings.h"

#include <cmath>

namespace novelty::eval {

MeanSelectivity MeanOver(const std::vector<SelectivityRow>& rows, const std::string& region,
                         int first, int last) {
  MeanSelectivity m;
  for (const SelectivityRow& r : rows) {
    if (r.region != region || r.frame < first || r.frame > last) continue;
    if (!std::isfinite(r.surprise.as_db) || !std::isfinite(r.difference.as_db)) continue;
    m.as_surprise += r.surprise.as_db, m.pas_surprise += r.surprise.pas_db;
    m.as_difference += r.difference.as_db, m.pas_difference += r.difference.pas_db;
    m.coverage += r.surprise.coverage;
    ++m.frames;
  }
  if (m.frames > 0) {
    for (double* v :
         {&m.as_surprise, &m.pas_surprise, &m.as_difference, &m.pas_difference, &m.coverage})
      *v /= m.frames;
  }
  return m;
}

namespace {

bool Holds(Claim claim, const MeanSelectivity& m) {
  if (m.frames == 0) return false;
  switch (claim) {
    case Claim::kSurpriseMoreSelective:
      return m.as_surprise > m.as_difference;
    case Claim::kBothDetect:
      return m.pas_surprise > 0.0 && m.pas_difference > 0.0;
    case Claim::kSurpriseLessSelective:
      return m.as_surprise < m.as_difference;
  }
  return false;
}

}  // namespace

FindingResult Evaluate(const std::vector<SelectivityRow>& rows, const Finding& finding) {
  FindingResult r;
  r.mean = MeanOver(rows, finding.region, finding.first, finding.last);
  r.holds = Holds(finding.claim, r.mean);
  return r;
}

bool SurpriseLosesLess(const MeanSelectivity& full, const MeanSelectivity& sparse) {
  if (full.frames == 0 || sparse.frames == 0) return false;
  return full.pas_surprise - sparse.pas_surprise < full.pas_difference - sparse.pas_difference;
}

}  // namespace novelty::eval
