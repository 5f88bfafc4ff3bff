#include "sim/world/pioneer3dx.h"

#include <gtest/gtest.h>

#include <cmath>

namespace novelty::sim {
namespace {

// Drives until odometry reports `distance` metres, then stops and lets the robot come to rest.
void DriveStraight(PhysicsWorld& world, Pioneer3dx& robot, double distance, double speed) {
  const Odometry start = robot.odometry();
  auto travelled = [&] {
    return std::hypot(robot.odometry().x - start.x, robot.odometry().y - start.y);
  };
  while (travelled() < distance) {
    // Slow down over the last 10 cm so the stop does not overshoot.
    const double remaining = distance - travelled();
    robot.Command(std::max(0.02, std::min(speed, 2.0 * remaining)), 0.0);
    robot.Step();
    ASSERT_LT(world.time(), 60.0) << "robot does not move";
  }
  robot.Command(0.0, 0.0);
  for (int i = 0; i < 1000; ++i) robot.Step();
}

TEST(Pioneer3dx, RestsOnItsWheelsAndCaster) {
  PhysicsWorld world;
  Pioneer3dx robot(world, 0.0, 0.0, 0.3);
  world.Advance(1.0);
  const Eigen::Vector3d p = robot.TruePose2D();
  EXPECT_NEAR(p.x(), 0.0, 1e-3);
  EXPECT_NEAR(p.y(), 0.0, 1e-3);
  EXPECT_NEAR(p.z(), 0.3, 1e-3);
  // Base frame on the floor, upright.
  EXPECT_NEAR(robot.TruePose().translation().z(), 0.0, 3e-3);
  EXPECT_GT((robot.TruePose().linear() * Eigen::Vector3d::UnitZ()).z(), 0.999);
}

TEST(Pioneer3dx, OneMetreStraightDriveEndsWithinOneCentimetre) {
  PhysicsWorld world;
  const double heading = 0.4;
  Pioneer3dx robot(world, 1.0, 2.0, heading);
  world.Advance(0.5);
  DriveStraight(world, robot, 1.0, 0.4);
  const Eigen::Vector3d p = robot.TruePose2D();
  const Eigen::Vector2d target =
      Eigen::Vector2d(1.0, 2.0) + Eigen::Vector2d(std::cos(heading), std::sin(heading));
  EXPECT_LT((p.head<2>() - target).norm(), 0.01) << "ended at " << p.transpose();
  EXPECT_NEAR(std::remainder(p.z() - heading, 2 * M_PI), 0.0, 0.01);
}

// Like a real robot's, the odometry drifts when the wheels slip: a few percent, not more.
TEST(Pioneer3dx, OdometryFollowsATurnAndDriftsLikeARealRobot) {
  PhysicsWorld world;
  Pioneer3dx robot(world, 0.0, 0.0, 0.0);
  world.Advance(0.5);
  // Quarter circle of radius 1 m at 0.3 m/s: w = v / r (open loop, so it ends roughly there).
  const double duration = (M_PI / 2) / 0.3;
  for (double t = 0; t < duration; t += world.options().time_step) {
    robot.Command(0.3, 0.3);
    robot.Step();
  }
  robot.Command(0, 0);
  for (int i = 0; i < 500; ++i) robot.Step();
  const Eigen::Vector3d truth = robot.TruePose2D();
  const Odometry& odo = robot.odometry();
  EXPECT_NEAR(truth.z(), M_PI / 2, 0.15);  // turned about a quarter
  const double path = M_PI / 2;            // metres along the arc
  const double error = std::hypot(odo.x - truth.x(), odo.y - truth.y());
  EXPECT_LT(error, 0.03 * path);
  EXPECT_GT(error, 0.001 * path) << "odometry that never drifts is not realistic";
  EXPECT_LT(std::abs(std::remainder(odo.phi - truth.z(), 2 * M_PI)), 4.0 * M_PI / 180);
  EXPECT_GT(odo.left_ticks, 0);
  EXPECT_GT(odo.right_ticks, odo.left_ticks);  // the outer (right) wheel turned more
}

}  // namespace
}  // namespace novelty::sim
