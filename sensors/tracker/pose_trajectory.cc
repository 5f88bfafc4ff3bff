#include "sensors/tracker/pose_trajectory.h"

#include <algorithm>
#include <cmath>

namespace novelty::sensors {

Eigen::Isometry3d InterpolatePose(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b,
                                  double s) {
  const Eigen::Quaterniond qa(a.linear()), qb(b.linear());
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  result.linear() = qa.slerp(s, qb).toRotationMatrix();  // Eigen's slerp takes the short arc
  result.translation() = (1.0 - s) * a.translation() + s * b.translation();
  return result;
}

PoseTrajectory::PoseTrajectory(std::vector<TimedPose> poses) : poses_(std::move(poses)) {
  // std::sort, not stable_sort: the latter's temporary buffer ignores Eigen's over-alignment.
  std::sort(poses_.begin(), poses_.end(),
            [](const TimedPose& x, const TimedPose& y) { return x.time < y.time; });
}

std::optional<Eigen::Isometry3d> PoseTrajectory::At(double t,
                                                    const PoseInterpolationOptions& options,
                                                    std::string* why) const {
  auto fail = [&](const std::string& reason) -> std::optional<Eigen::Isometry3d> {
    if (why) *why = reason;
    return std::nullopt;
  };
  if (poses_.empty()) return fail("no tracker poses");
  if (t < poses_.front().time || t > poses_.back().time)
    return fail("time " + std::to_string(t) + " s outside the tracked span");
  auto after = std::lower_bound(poses_.begin(), poses_.end(), t,
                                [](const TimedPose& p, double x) { return p.time < x; });
  if (after->time == t && options.smoothing_half_window <= 0) return after->pose;
  const auto before = after == poses_.begin() ? after : after - 1;
  if (after->time - before->time > options.max_gap)
    return fail("tracker gap of " + std::to_string(after->time - before->time) + " s at " +
                std::to_string(t) + " s");
  const double span = after->time - before->time;
  const Eigen::Isometry3d slerp =
      span > 0 ? InterpolatePose(before->pose, after->pose, (t - before->time) / span)
               : after->pose;
  if (options.smoothing_half_window <= 0) return slerp;
  return LocalLinearFit(t, slerp, options.smoothing_half_window);
}

Eigen::Isometry3d PoseTrajectory::LocalLinearFit(double t, const Eigen::Isometry3d& center,
                                                 double half_window) const {
  // Weighted least squares y(dt) = y0 + y1·dt with tricube weights; the estimate is y0.
  auto first = std::lower_bound(poses_.begin(), poses_.end(), t - half_window,
                                [](const TimedPose& p, double x) { return p.time < x; });
  double s0 = 0, s1 = 0, s2 = 0;
  Eigen::Matrix<double, 6, 1> y0 = Eigen::Matrix<double, 6, 1>::Zero(), y1 = y0;
  const Eigen::Matrix3d center_inv = center.linear().transpose();
  for (auto p = first; p != poses_.end() && p->time <= t + half_window; ++p) {
    const double dt = p->time - t, u = std::abs(dt) / half_window;
    const double w = std::pow(1.0 - u * u * u, 3);
    Eigen::Matrix<double, 6, 1> y;
    const Eigen::AngleAxisd delta(center_inv * p->pose.linear());
    y.head<3>() = delta.angle() * delta.axis();
    y.tail<3>() = p->pose.translation();
    s0 += w, s1 += w * dt, s2 += w * dt * dt;
    y0 += w * y, y1 += w * dt * y;
  }
  const double det = s0 * s2 - s1 * s1;
  if (s0 <= 0 || det <= 1e-12 * s0 * s0) return center;  // too few samples for a line
  const Eigen::Matrix<double, 6, 1> fit = (s2 * y0 - s1 * y1) / det;
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d r = fit.head<3>();
  result.linear() = center.linear() *
                    (r.norm() > 0 ? Eigen::AngleAxisd(r.norm(), r.normalized()).toRotationMatrix()
                                  : Eigen::Matrix3d::Identity());
  result.translation() = fit.tail<3>();
  return result;
}

}  // namespace novelty::sensors
