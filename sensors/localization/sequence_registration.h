// Registration of an image sequence to the common frame of the first (thesis 6.1.1): visual
// localization gives each sequence m its own frame; a few support views j_n of it are also
// localized in the common frame (S) besides their own (M). Each gives the transform between the
// frames Q_n = S_n · M_n⁻¹ (eq. 6.1); these differ because of the drift along the sequence, so Q
// is interpolated over the frame index j and every pose mapped as S_j = Q_j · M_j (eq. 6.3).
//
// Two ways to interpolate Q_j:
//  - the thesis's (eq. 6.2): second-order Lagrange polynomials through three support views, of
//    the rotation columns and the translation, columns normalised afterwards — which leaves them
//    non-orthogonal in general;
//  - a least-squares fit with Ceres: Q_j = exp([a + b·j + c·j²]×)·R̄ on SO(3) and t_j quadratic
//    in j, over any number (≥ 3) of support views, always a rotation.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "core/eigen_abi.h"

namespace novelty::sensors {

struct SupportView {
  double index = 0;                      ///< j: frame index (or time) in the sequence
  Eigen::Isometry3d common_from_camera;  ///< S: pose in the common frame
  Eigen::Isometry3d own_from_camera;     ///< M: pose in the sequence's own frame
};

/// Q_j by eq. 6.2 from the first three support views (the matrix may be non-orthogonal).
/// Throws std::invalid_argument with fewer than three or two at the same index.
Eigen::Matrix4d LagrangeFrameTransform(const std::vector<SupportView>& support, double j);

struct FrameFitOptions {
  /// Metres per radian: how rotation residuals weigh against position residuals (1 rad ~ 1 m:
  /// alike for a room-sized scene).
  double rotation_weight = 1.0;
  /// Huber scale (m) of each support view's residual: a support view that aligned wrongly (under
  /// another lighting one can be centimetres off) pulls the fit linearly, not quadratically.
  /// 0 = plain least squares for this first fit.
  double robust_scale = 0.005;
  /// Then refit from there with a Cauchy loss of this scale (m), whose pull fades with the
  /// distance: under another lighting several support views can be biased alike by 1–1.5 cm
  /// (phase I5: 5 of 12), too many for the Huber fit, which still pulls linearly. 0 = the first
  /// fit only (plain least squares needs both at 0).
  double outlier_scale = 0.003;
};

/// The Ceres fit of Q_j; evaluate with At(). Throws std::invalid_argument with fewer
/// than three support views.
class FittedFrameTransform {
 public:
  explicit FittedFrameTransform(const std::vector<SupportView>& support,
                                const FrameFitOptions& options = {});
  Eigen::Isometry3d At(double j) const;

 private:
  enum class Loss { kNone, kHuber, kCauchy };
  void Solve(const std::vector<SupportView>& support, const FrameFitOptions& options, Loss loss);

  Eigen::Matrix3d reference_rotation_;
  double center_ = 0, scale_ = 1;  // j is normalised to (j − center) / scale for conditioning
  double rotation_[9] = {0};       // a, b, c (angle-axis coefficients)
  double translation_[9] = {0};    // t0, t1, t2
};

/// S_j = Q_j · M_j (eq. 6.3) for a 4×4 Q (orthogonal or not).
Eigen::Matrix4d RegisterPose(const Eigen::Matrix4d& frame_transform,
                             const Eigen::Isometry3d& own_from_camera);

}  // namespace novelty::sensors
