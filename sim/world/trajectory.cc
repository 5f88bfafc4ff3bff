#include "sim/world/trajectory.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace novelty::sim {

namespace {

// Distance along a trapezoidal (or triangular) profile of total length L at time t, and speed.
void Profile(double L, double vmax, double a, double t, double* s, double* v) {
  const double t_acc = std::min(vmax / a, std::sqrt(L / a));
  const double v_peak = a * t_acc;
  const double s_acc = 0.5 * a * t_acc * t_acc;
  const double t_cruise = (L - 2 * s_acc) / v_peak;
  const double total = 2 * t_acc + t_cruise;
  t = std::clamp(t, 0.0, total);
  if (t < t_acc) {
    *s = 0.5 * a * t * t;
    *v = a * t;
  } else if (t < t_acc + t_cruise) {
    *s = s_acc + v_peak * (t - t_acc);
    *v = v_peak;
  } else {
    const double r = total - t;
    *s = L - 0.5 * a * r * r;
    *v = a * r;
  }
}

double ProfileDuration(double L, double vmax, double a) {
  const double t_acc = std::min(vmax / a, std::sqrt(L / a));
  const double v_peak = a * t_acc;
  return 2 * t_acc + (L - a * t_acc * t_acc) / v_peak;
}

}  // namespace

void Trajectory::AddArc(const Eigen::Vector2d& centre, double radius, double from, double to,
                        double speed, double acceleration) {
  if (!(radius > 0 && speed > 0 && acceleration > 0) || from == to) {
    throw std::invalid_argument(
        "Trajectory::AddArc: need radius, speed, acceleration > 0 and "
        "from != to");
  }
  const double length = radius * std::abs(to - from);
  segments_.push_back({true, centre, radius, from, to, speed, acceleration,
                       ProfileDuration(length, speed, acceleration)});
}

void Trajectory::AddStop(double duration) {
  if (segments_.empty()) throw std::invalid_argument("Trajectory::AddStop: no segment to stop at");
  if (!(duration >= 0)) throw std::invalid_argument("Trajectory::AddStop: negative duration");
  Segment s = segments_.back();
  s.arc = false;
  s.duration = duration;
  segments_.push_back(s);
}

void Trajectory::Repeat(int times) {
  const std::vector<Segment> once = segments_;
  for (int i = 0; i < times; ++i) segments_.insert(segments_.end(), once.begin(), once.end());
}

double Trajectory::Duration() const {
  double d = 0.0;
  for (const Segment& s : segments_) d += s.duration;
  return d;
}

TrajectoryReference Trajectory::At(double t) const {
  if (segments_.empty()) throw std::logic_error("Trajectory::At on an empty trajectory");
  t = std::max(0.0, t);
  std::size_t i = 0;
  while (i + 1 < segments_.size() && t > segments_[i].duration) t -= segments_[i++].duration;
  const Segment& s = segments_[i];
  const double direction = s.to > s.from ? 1.0 : -1.0;
  double along = 0.0, speed = 0.0;
  if (s.arc) {
    Profile(s.radius * std::abs(s.to - s.from), s.speed, s.acceleration, t, &along, &speed);
  } else {
    along = s.radius * std::abs(s.to - s.from);  // a stop holds the end of its arc
  }
  const double phi = s.from + direction * along / s.radius;
  TrajectoryReference r;
  r.x = s.centre.x() + s.radius * std::cos(phi);
  r.y = s.centre.y() + s.radius * std::sin(phi);
  r.heading = phi + M_PI / 2;
  r.v = direction * speed;
  r.w = r.v / s.radius;
  return r;
}

Eigen::Vector2d TrackReference(const TrajectoryReference& ref, const Eigen::Vector3d& pose,
                               const TrackingGains& g) {
  const double c = std::cos(pose.z()), s = std::sin(pose.z());
  const double dx = ref.x - pose.x(), dy = ref.y - pose.y();
  const double ex = c * dx + s * dy, ey = -s * dx + c * dy;
  const double eth = std::remainder(ref.heading - pose.z(), 2 * M_PI);
  // Kanayama's law; the heading term uses |v_r| so that backward runs converge too.
  const double v = ref.v * std::cos(eth) + g.k_x * ex;
  const double w = ref.w + ref.v * g.k_y * ey + std::abs(ref.v) * g.k_theta * std::sin(eth);
  return {v, w};
}

}  // namespace novelty::sim
