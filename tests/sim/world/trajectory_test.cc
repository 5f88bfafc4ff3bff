#include "sim/world/trajectory.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/world/pioneer3dx.h"

namespace novelty::sim {
namespace {

TEST(Trajectory, ArcReferenceIsOnTheCircleFacingTheCentre) {
  Trajectory traj;
  const Eigen::Vector2d c(2.0, 1.0);
  traj.AddArc(c, 1.5, -0.5, 0.5, 0.2);
  traj.AddStop(2.0);
  traj.AddArc(c, 1.5, 0.5, -0.5, 0.2);
  EXPECT_NEAR(traj.Duration(), 2 * (1.5 / 0.2 + 0.2 / 0.3) + 2.0, 1e-9);  // trapezoid: L/v + v/a
  for (double t = 0; t <= traj.Duration(); t += 0.1) {
    const TrajectoryReference r = traj.At(t);
    EXPECT_NEAR(std::hypot(r.x - c.x(), r.y - c.y()), 1.5, 1e-12);
    // The robot's left (heading + 90°) points at the centre.
    const Eigen::Vector2d left(std::cos(r.heading + M_PI / 2), std::sin(r.heading + M_PI / 2));
    EXPECT_NEAR(left.dot((c - Eigen::Vector2d(r.x, r.y)).normalized()), 1.0, 1e-12);
    EXPECT_LE(std::abs(r.v), 0.2 + 1e-12);
  }
  EXPECT_NEAR(traj.At(traj.Duration() / 2).v, 0.0, 1e-12);  // stopped at Q2
  EXPECT_LT(traj.At(traj.Duration() - 3.0).v, 0.0);         // driving back
  const TrajectoryReference end = traj.At(traj.Duration());
  EXPECT_NEAR(end.x, c.x() + 1.5 * std::cos(-0.5), 1e-9);
}

TEST(Trajectory, RobotFollowsAnArcBackAndForth) {
  PhysicsWorld world;
  Trajectory traj;
  const Eigen::Vector2d c(0.0, 0.0);
  traj.AddArc(c, 1.6, -0.6, 0.6, 0.2);
  traj.AddStop(1.0);
  traj.AddArc(c, 1.6, 0.6, -0.6, 0.2);
  const TrajectoryReference start = traj.At(0.0);
  Pioneer3dx robot(world, start.x, start.y, start.heading);
  double worst_odometry = 0.0, worst_truth = 0.0;
  for (double t = 0; t < traj.Duration() + 1.0; t += world.options().time_step) {
    const TrajectoryReference ref = traj.At(t);
    const Odometry& o = robot.odometry();
    const Eigen::Vector2d cmd = TrackReference(ref, {o.x, o.y, o.phi});
    robot.Command(cmd.x(), cmd.y());
    robot.Step();
    worst_odometry = std::max(worst_odometry, std::hypot(o.x - ref.x, o.y - ref.y));
    const Eigen::Vector3d truth = robot.TruePose2D();
    worst_truth = std::max(worst_truth, std::abs(std::hypot(truth.x(), truth.y()) - 1.6));
  }
  EXPECT_LT(worst_odometry, 0.02);  // the controller tracks (in its own odometry frame)
  EXPECT_LT(worst_truth, 0.08);     // the true path stays near the circle despite drift
  const Eigen::Vector3d end = robot.TruePose2D();
  EXPECT_LT(std::hypot(end.x() - start.x, end.y() - start.y), 0.08);
}

}  // namespace
}  // namespace novelty::sim
