// Least-squares rigid transform between two corresponding point sets by the SVD of their inertia
// matrix (thesis eq. 3.1–3.3, [AHB87]), with per-point weights (eq. 3.4). Shared by the LED
// tracker (plate LEDs → measured LEDs) and visual localization (map points → triangulated points).
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "core/eigen_abi.h"

namespace novelty::sensors {

struct RigidFitResult {
  /// T with measured_i ≈ T · model_i.
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  /// Weighted RMS of |measured_i − T·model_i| (m).
  double rms = 0.0;
  /// True when the plain SVD solution was a reflection (det < 0) and was turned into the nearest
  /// rotation by flipping the axis of the smallest singular value (Umeyama 1991). For coplanar
  /// points (the LED plate) that is routine and exact; for a mirrored set the residual stays large.
  bool reflection_corrected = false;
};

/// Fits T. `weights` may be empty (all 1); otherwise one non-negative weight per point. Returns
/// nullopt and sets `why` when fewer than three points carry weight, the sizes differ, or the
/// model points are (nearly) collinear so the rotation is not determined.
std::optional<RigidFitResult> FitRigid(const std::vector<Eigen::Vector3d>& model,
                                       const std::vector<Eigen::Vector3d>& measured,
                                       const std::vector<double>& weights, std::string* why);

}  // namespace novelty::sensors
