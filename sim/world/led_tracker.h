// The ceiling LED tracker of 3.1.2: four LEDs at the corners of a rectangular plate on top of
// the camera head, measured in world coordinates at 25 Hz with about 1 mm noise and occasional
// dropouts of single LEDs (occlusion, radio loss).
//
// Plate frame (defined once, resolving the two descriptions of 3.1.2): origin at LED 4, x axis
// towards LED 1, y axis towards LED 3, z = x × y; LEDs 1-4 at (a,0,0), (a,b,0), (0,b,0), (0,0,0).
// The plate lies on top of the head, perpendicular to the image plane.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <random>

namespace novelty::sim {

struct LedTrackerSpec {
  double plate_length = 0.20;  ///< a: LED 4 → LED 1 (m)
  double plate_width = 0.12;   ///< b: LED 4 → LED 3 (m)
  /// Pose of the plate frame in the camera-head frame (camera +Z forward, +X right, +Y down):
  /// centred 8 cm above the optical centre, plate x along the optical axis, y to the right.
  Eigen::Isometry3d head_from_plate = DefaultPlatePose();
  double rate_hz = 25.0;
  double noise_std = 0.001;           ///< per coordinate (m)
  double dropout_probability = 0.02;  ///< per LED and measurement

  static Eigen::Isometry3d DefaultPlatePose();
  /// LED i (0…3 for LEDs 1…4) in plate coordinates.
  Eigen::Vector3d LedInPlate(int i) const;
};

/// One tracker sample: each LED's measured world position, or none when it dropped out.
using LedMeasurement = std::array<std::optional<Eigen::Vector3d>, 4>;

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
