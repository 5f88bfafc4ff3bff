#include "sim/world/led_tracker.h"

namespace novelty::sim {

LedMeasurement LedTracker::Measure(const Eigen::Isometry3d& world_from_head) {
  std::normal_distribution<double> noise(0.0, spec_.noise_std);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  LedMeasurement m;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d truth =
        world_from_head * spec_.plate.camera_from_plate * spec_.plate.leds[i];
    const Eigen::Vector3d noisy = truth + Eigen::Vector3d(noise(rng_), noise(rng_), noise(rng_));
    if (uniform(rng_) >= spec_.dropout_probability) m[i] = noisy;
  }
  return m;
}

}  // namespace novelty::sim
