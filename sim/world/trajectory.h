// Reference trajectories of the thesis's experiments and a controller that follows them:
// arcs around a centre with the robot's left side (and a camera mounted to the left) facing the
// centre, driven forward or backward (4.3: Q1 → Q2 and back; 6.4: quarter circles), and stops.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace novelty::sim {

/// Reference state at one time: planar pose and body velocities.
struct TrajectoryReference {
  double x = 0.0, y = 0.0, heading = 0.0;
  double v = 0.0, w = 0.0;
};

class Trajectory {
 public:
  /// An arc around `centre` of `radius` from polar angle `from` to `to` (rad). The robot heads
  /// along the counter-clockwise tangent (heading = angle + π/2) so its left faces the centre; if
  /// to < from it drives backward. Trapezoidal speed profile with `speed` and `acceleration`.
  void AddArc(const Eigen::Vector2d& centre, double radius, double from, double to, double speed,
              double acceleration = 0.3);
  /// Standing still for `duration` seconds at the end of the previous segment.
  void AddStop(double duration);
  /// Appends the segments added so far `times` more times (back-and-forth runs).
  void Repeat(int times);

  double Duration() const;
  bool empty() const { return segments_.empty(); }
  std::size_t size() const { return segments_.size(); }  ///< arcs and stops
  /// Reference at time t (clamped to [0, Duration()]).
  TrajectoryReference At(double t) const;

 private:
  struct Segment {
    bool arc;
    Eigen::Vector2d centre;
    double radius, from, to, speed, acceleration, duration;
  };
  std::vector<Segment> segments_;
};

/// Gains of the tracking controller (Kanayama et al. 1990), applied to the odometry pose.
struct TrackingGains {
  double k_x = 1.0;      ///< 1/s, along-track error
  double k_y = 20.0;     ///< 1/m², cross-track error
  double k_theta = 3.0;  ///< 1/m, heading error
};

/// Body velocities (v, w) that steer a robot at (x, y, heading) onto the reference.
Eigen::Vector2d TrackReference(const TrajectoryReference& ref, const Eigen::Vector3d& pose,
                               const TrackingGains& gains = {});

}  // namespace novelty::sim
