// The ceiling LED tracker of 3.1.2: four LEDs at the corners of a rectangular plate on top of
// the camera head, measured in world coordinates at 25 Hz with about 1 mm noise and occasional
// dropouts of single LEDs (occlusion, radio loss). The plate, its frame and its mount on the head
// are sensors/tracker/led_plate.h's, so simulation and calibration cannot disagree.
#pragma once

#include <Eigen/Geometry>
#include <random>

#include "sensors/tracker/led_plate.h"

namespace novelty::sim {

using sensors::LedMeasurement;

struct LedTrackerSpec {
  /// LED positions and T_head_plate (head = the rig's reference camera).
  sensors::LedPlate plate = sensors::LedPlate::Nominal();
  double rate_hz = 25.0;
  double noise_std = 0.001;           ///< per coordinate (m)
  double dropout_probability = 0.02;  ///< per LED and measurement
};

class LedTracker {
 public:
  LedTracker(const LedTrackerSpec& spec, std::uint64_t seed) : spec_(spec), rng_(seed) {}
  /// Measures the LEDs for the true head pose T_world_head.
  LedMeasurement Measure(const Eigen::Isometry3d& world_from_head);
  const LedTrackerSpec& spec() const { return spec_; }

 private:
  LedTrackerSpec spec_;
  std::mt19937_64 rng_;
};

}  // namespace novelty::sim
