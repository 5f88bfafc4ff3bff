#include "sim/world/led_tracker.h"

namespace novelty::sim {

Eigen::Isometry3d LedTrackerSpec::DefaultPlatePose() {
  // Plate axes in head coordinates: x → head +Z (forward), y → head +X (right), z = x × y = head
  // -Y (up). Origin (LED 4) at the plate's rear-left corner, 8 cm above the optical centre.
  Eigen::Matrix3d r;
  r.col(0) = Eigen::Vector3d::UnitZ();
  r.col(1) = Eigen::Vector3d::UnitX();
  r.col(2) = -Eigen::Vector3d::UnitY();
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = r;
  t.translation() = Eigen::Vector3d(-0.06, -0.08, -0.10);  // x: -b/2, y: 8 cm up, z: -a/2
  return t;
}

Eigen::Vector3d LedTrackerSpec::LedInPlate(int i) const {
  const double a = plate_length, b = plate_width;
  const Eigen::Vector3d leds[4] = {{a, 0, 0}, {a, b, 0}, {0, b, 0}, {0, 0, 0}};
  return leds[i];
}

LedMeasurement LedTracker::Measure(const Eigen::Isometry3d& world_from_head) {
  std::normal_distribution<double> noise(0.0, spec_.noise_std);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  LedMeasurement m;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d truth = world_from_head * spec_.head_from_plate * spec_.LedInPlate(i);
    const Eigen::Vector3d noisy = truth + Eigen::Vector3d(noise(rng_), noise(rng_), noise(rng_));
    if (uniform(rng_) >= spec_.dropout_probability) m[i] = noisy;
  }
  return m;
}

}  // namespace novelty::sim
