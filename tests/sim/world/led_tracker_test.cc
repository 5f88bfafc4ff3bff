#include "sim/world/led_tracker.h"

#include <gtest/gtest.h>

namespace novelty::sim {
namespace {

Eigen::Isometry3d SomeHeadPose() {
  Eigen::Isometry3d head = Eigen::Isometry3d::Identity();
  // Camera looking along world +x, level: camera +Z → world +x, +X → world -y, +Y → world -z.
  head.linear().col(0) = -Eigen::Vector3d::UnitY();
  head.linear().col(1) = -Eigen::Vector3d::UnitZ();
  head.linear().col(2) = Eigen::Vector3d::UnitX();
  head.translation() = Eigen::Vector3d(1.0, 2.0, 1.1);
  return head;
}

TEST(LedTracker, NoiselessLedsFormThePlateFrame) {
  LedTrackerSpec spec;
  spec.noise_std = 0.0;
  spec.dropout_probability = 0.0;
  LedTracker tracker(spec, 1);
  const LedMeasurement m = tracker.Measure(SomeHeadPose());
  for (const auto& led : m) ASSERT_TRUE(led.has_value());
  const Eigen::Vector3d l1 = *m[0], l2 = *m[1], l3 = *m[2], l4 = *m[3];
  const double a = 0.20, b = 0.12;          // the nominal XB3 plate
  EXPECT_NEAR((l1 - l4).norm(), a, 1e-12);  // LED 4 → 1: plate x
  EXPECT_NEAR((l3 - l4).norm(), b, 1e-12);  // LED 4 → 3: plate y
  EXPECT_NEAR((l2 - l4).norm(), std::hypot(a, b), 1e-12);
  EXPECT_NEAR((l1 - l4).dot(l3 - l4), 0.0, 1e-12);  // rectangle
  // On a level head the plate is horizontal, 8 cm above the optical centre, x along the view.
  for (const auto& led : m) EXPECT_NEAR(led->z(), 1.18, 1e-12);
  EXPECT_NEAR((l1 - l4).normalized().x(), 1.0, 1e-12);
  EXPECT_NEAR(((l1 + l3) / 2 - Eigen::Vector3d(1.0, 2.0, 1.18)).norm(), 0.0, 1e-12);  // centred
}

TEST(LedTracker, NoiseAndDropoutsHaveTheConfiguredStatistics) {
  LedTrackerSpec spec;  // 1 mm noise, 2 % dropouts
  LedTracker noisy(spec, 42);
  LedTrackerSpec exact_spec = spec;
  exact_spec.noise_std = 0.0;
  exact_spec.dropout_probability = 0.0;
  LedTracker exact(exact_spec, 0);
  const LedMeasurement truth = exact.Measure(SomeHeadPose());
  double sum2 = 0.0;
  int samples = 0, dropped = 0;
  for (int i = 0; i < 5000; ++i) {
    const LedMeasurement m = noisy.Measure(SomeHeadPose());
    for (int k = 0; k < 4; ++k) {
      if (!m[k]) {
        ++dropped;
        continue;
      }
      sum2 += (*m[k] - *truth[k]).squaredNorm();
      samples += 3;
    }
  }
  EXPECT_NEAR(std::sqrt(sum2 / samples), 0.001, 0.00003);
  EXPECT_NEAR(dropped / 20000.0, 0.02, 0.004);
}

}  // namespace
}  // namespace novelty::sim
