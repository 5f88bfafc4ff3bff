// The LED plate on the camera head (thesis 3.1.2) and its calibration.
//
// Plate frame, defined once for the whole project (3.1.2 describes it in two slightly different
// ways): origin at LED 4, x axis towards LED 1, y axis in the plane of LEDs 1, 3, 4 towards LED 3
// (orthogonalised against x), z = x × y. A nominal rectangular plate has LEDs 1–4 at (a,0,0),
// (a,b,0), (0,b,0), (0,0,0). The simulator's tracker and the calibration below both use this.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/eigen_abi.h"

namespace novelty::sensors {

/// One tracker sample: each LED's measured world position (index 0…3 = LED 1…4), or none when
/// it was not seen.
using LedMeasurement = std::array<std::optional<Eigen::Vector3d>, 4>;

struct LedSample {
  double time = 0.0;  ///< seconds
  LedMeasurement leds;
};

struct LedPlate {
  /// LED 1…4 in plate coordinates (m).
  std::array<Eigen::Vector3d, 4> leds;
  /// T_cam_plate: the plate frame in the camera frame (+Z forward, +X right, +Y down).
  Eigen::Isometry3d camera_from_plate = Eigen::Isometry3d::Identity();

  /// A rectangular a × b plate (defaults: the XB3 head's 20 × 12 cm plate) mounted as on the
  /// thesis's camera head: plate x along the optical axis, y to the right, origin a/2 behind and
  /// b/2 left of the optical centre and 8 cm above it; plate z = x × y points down.
  static LedPlate Nominal(double a = 0.20, double b = 0.12, double height = 0.08);
};

/// Plate frame from four LED positions given in any frame: returns T_any_plate.
Eigen::Isometry3d PlateFrameFromLeds(const std::array<Eigen::Vector3d, 4>& leds);

struct StaticIntervalOptions {
  /// Shortest interval accepted as static (s).
  double min_duration = 1.0;
  /// An LED counts as still while it stays within this distance of its mean (m); about 4× the
  /// tracker's 1 mm noise.
  double tolerance = 0.004;
};

/// The longest run of consecutive samples, starting and ending with all four LEDs seen, in which
/// every LED stays within `tolerance` of its running mean (samples missing an LED are kept; that
/// LED is not checked in them); nullopt (with `why`) when none lasts `min_duration`.
std::optional<std::pair<size_t, size_t>> FindStaticInterval(const std::vector<LedSample>& samples,
                                                            const StaticIntervalOptions& options,
                                                            std::string* why);

/// Calibrates the plate from samples taken while the head stood still (3.1.2): each LED's
/// position is averaged over time and expressed in the plate frame. `camera_from_plate` is taken
/// from `mount` (the head's mechanical calibration). Throws std::runtime_error when an LED is
/// never seen or the LEDs do not form a plate (collinear, sides < 2 cm).
LedPlate CalibratePlateGeometry(const std::vector<LedSample>& static_samples,
                                const Eigen::Isometry3d& mount);

/// T_cam_plate from pairs (T_world_plate, T_world_cam) observed at the same instants — e.g. a
/// static interval in which the camera pose is known from a calibration target or ground truth.
/// The rotation is the chordal mean (projected onto SO(3) by SVD), the translation the mean.
Eigen::Isometry3d EstimateCameraFromPlate(
    const std::vector<std::pair<Eigen::Isometry3d, Eigen::Isometry3d>>& world_plate_and_cam);

}  // namespace novelty::sensors
