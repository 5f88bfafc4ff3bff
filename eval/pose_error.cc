#include "eval/pose_error.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace novelty::eval {

std::optional<PoseErrorSummary> ComparePoses(const std::map<int, Eigen::Isometry3d>& estimated,
                                             const std::map<int, Eigen::Isometry3d>& truth) {
  std::vector<double> angle, shift;
  PoseErrorSummary s;
  for (const auto& [frame, pose] : estimated) {
    const auto g = truth.find(frame);
    if (g == truth.end()) continue;
    s.last_frame = frame;
    s.last_deg =
        Eigen::AngleAxisd(pose.linear().transpose() * g->second.linear()).angle() * 180 / M_PI;
    s.last_mm = (pose.translation() - g->second.translation()).norm() * 1000;
    angle.push_back(s.last_deg);
    shift.push_back(s.last_mm);
  }
  if (angle.empty()) return std::nullopt;
  s.frames = int(angle.size());
  std::sort(angle.begin(), angle.end());
  std::sort(shift.begin(), shift.end());
  s.median_deg = angle[angle.size() / 2], s.p95_deg = angle[angle.size() * 95 / 100];
  s.median_mm = shift[shift.size() / 2], s.p95_mm = shift[shift.size() * 95 / 100];
  return s;
}

}  // namespace novelty::eval
