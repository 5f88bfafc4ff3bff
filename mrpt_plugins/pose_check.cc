#include "mrpt_plugins/pose_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace novelty::mrpt_plugins {

namespace {

constexpr double kMinInterval = 0.1;  // s: timestamps closer than this (or none) count as 0.1 s

std::string Format(const char* format, double a, double b) {
  char text[256];
  std::snprintf(text, sizeof text, format, a, b);
  return text;
}

}  // namespace

const OptionTable<PoseCheckOptions>& PoseCheckOptionTable() {
  using O = PoseCheckOptions;
  static const OptionTable<O> table = [] {
    OptionTable<O> t;
    t.Add(
         "max_speed", [](O & o) -> auto& { return o.max_speed; },
         "m/s; a warning when the camera moves faster between frames (0 = no check)")
        .Add(
            "max_turn_rate_deg", [](O & o) -> auto& { return o.max_turn_rate; },
            "deg/s; ... or turns faster (0 = no check)", M_PI / 180.0)
        .Add(
            "max_tilt_deg", [](O & o) -> auto& { return o.max_tilt; },
            "deg; ... or its image's up is tilted more from the world's +z (0 = no check)",
            M_PI / 180.0)
        .Add(
            "min_height", [](O & o) -> auto& { return o.min_height; },
            "m; ... or it is lower (below the floor, z = 0)")
        .Check([](const O& o) {
          CheckNotNegative(o.max_speed, "max_speed");
          CheckNotNegative(o.max_turn_rate, "max_turn_rate_deg");
          CheckNotNegative(o.max_tilt, "max_tilt_deg");
          if (!std::isfinite(o.min_height))
            throw std::invalid_argument("min_height must be finite");
        });
    return t;
  }();
  return table;
}

std::string PoseCheck::Check(const Eigen::Isometry3d& T_world_cam, double time) {
  std::string problems;
  const auto add = [&problems](const std::string& p) {
    problems += (problems.empty() ? "" : "; ") + p;
  };
  const Eigen::Vector3d up = -T_world_cam.linear().col(1);  // image up: camera -Y
  const double tilt = std::acos(std::clamp(up.z() / up.norm(), -1.0, 1.0));
  if (options_.max_tilt > 0 && tilt > options_.max_tilt)
    add(Format("camera tilted %.0f deg from upright (limit %.0f deg)", tilt * 180 / M_PI,
               options_.max_tilt * 180 / M_PI));
  if (T_world_cam.translation().z() < options_.min_height)
    add(Format("camera %.2f m below the floor (limit %.2f m)", -T_world_cam.translation().z(),
               -options_.min_height));
  if (last_) {
    const double dt = std::isfinite(time) && std::isfinite(last_->time)
                          ? std::max(std::abs(time - last_->time), kMinInterval)
                          : kMinInterval;
    const double step = (T_world_cam.translation() - last_->T_world_cam.translation()).norm();
    const double turn =
        Eigen::AngleAxisd(last_->T_world_cam.linear().transpose() * T_world_cam.linear()).angle();
    if (options_.max_speed > 0 && step > options_.max_speed * dt)
      add(Format("camera moved %.2f m in %.2f s", step, dt));
    if (options_.max_turn_rate > 0 && turn > options_.max_turn_rate * dt)
      add(Format("camera turned %.0f deg in %.2f s", turn * 180 / M_PI, dt));
  }
  last_ = Last{T_world_cam, time};
  if (!problems.empty()) ++warnings_;
  return problems;
}

}  // namespace novelty::mrpt_plugins
