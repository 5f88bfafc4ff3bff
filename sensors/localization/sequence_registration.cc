#include "sensors/localization/sequence_registration.h"

#include <ceres/ceres.h>
#include <ceres/rotation.h>

#include <stdexcept>

namespace novelty::sensors {
namespace {

void CheckSupport(const std::vector<SupportView>& support) {
  if (support.size() < 3)
    throw std::invalid_argument("registration needs at least three support views, got " +
                                std::to_string(support.size()));
  for (size_t a = 0; a < support.size(); ++a)
    for (size_t b = a + 1; b < support.size(); ++b)
      if (support[a].index == support[b].index)
        throw std::invalid_argument("two support views at frame " +
                                    std::to_string(support[a].index));
}

// Residual of one support view n: how far its registered pose Q(j_n)·M_n lies from where it was
// localized, S_n — the rotation angle-axis of S_nᵀ·Q(j_n)·M_n weighted by `rotation_weight`
// (m/rad) and the position gap Q(j_n)·M_n.t − S_n.t in metres. Measured on the registered pose,
// not on Q: Q's translation is coupled to its rotation through the lever arm M_n.t (metres from
// the sequence's origin), so fitting Q's parts separately lets a small rotation error become a
// large position error of the cameras.
struct SupportResidual {
  SupportResidual(const SupportView& view, const Eigen::Matrix3d& reference, double x,
                  double rotation_weight)
      : view_(view), reference_(reference), x_(x), w_(rotation_weight) {}

  template <typename T>
  bool operator()(const T* rotation, const T* translation, T* residual) const {
    // ω(x) = a + b·x + c·x²; Q_R(x) = exp([ω]×)·R̄
    T omega[3];
    for (int k = 0; k < 3; ++k)
      omega[k] = rotation[k] + rotation[3 + k] * T(x_) + rotation[6 + k] * T(x_ * x_);
    using Matrix3 = Eigen::Matrix<T, 3, 3>;
    using Vector3 = Eigen::Matrix<T, 3, 1>;
    Matrix3 delta;
    ceres::AngleAxisToRotationMatrix(omega, ceres::ColumnMajorAdapter3x3(delta.data()));
    const Matrix3 q_rotation = delta * reference_.cast<T>();
    Vector3 q_translation;
    for (int k = 0; k < 3; ++k)
      q_translation(k) =
          translation[k] + translation[3 + k] * T(x_) + translation[6 + k] * T(x_ * x_);
    const Matrix3 e = view_.common_from_camera.linear().transpose().cast<T>() * q_rotation *
                      view_.own_from_camera.linear().cast<T>();
    T angle_axis[3];
    ceres::RotationMatrixToAngleAxis(ceres::ColumnMajorAdapter3x3(e.data()), angle_axis);
    const Vector3 position = q_rotation * view_.own_from_camera.translation().cast<T>() +
                             q_translation - view_.common_from_camera.translation().cast<T>();
    for (int k = 0; k < 3; ++k) {
      residual[k] = T(w_) * angle_axis[k];
      residual[3 + k] = position(k);
    }
    return true;
  }

  SupportView view_;
  Eigen::Matrix3d reference_;
  double x_, w_;
};

}  // namespace

Eigen::Matrix4d LagrangeFrameTransform(const std::vector<SupportView>& support, double j) {
  CheckSupport(support);
  const double j0 = support[0].index, j1 = support[1].index, j2 = support[2].index;
  const double l[3] = {(j - j1) * (j - j2) / ((j0 - j1) * (j0 - j2)),
                       (j - j0) * (j - j2) / ((j1 - j0) * (j1 - j2)),
                       (j - j0) * (j - j1) / ((j2 - j0) * (j2 - j1))};  // eq. 6.2
  Eigen::Matrix4d q = Eigen::Matrix4d::Zero();
  for (int n = 0; n < 3; ++n)
    q +=
        l[n] *
        (support[n].common_from_camera * support[n].own_from_camera.inverse()).matrix();  // eq. 6.1
  for (int c = 0; c < 3; ++c) q.block<3, 1>(0, c).normalize();  // columns to unit length
  q.row(3) << 0, 0, 0, 1;
  return q;
}

FittedFrameTransform::FittedFrameTransform(const std::vector<SupportView>& support,
                                           const FrameFitOptions& options) {
  CheckSupport(support);
  double lo = support[0].index, hi = lo;
  for (const auto& s : support) lo = std::min(lo, s.index), hi = std::max(hi, s.index);
  center_ = (lo + hi) / 2;
  scale_ = std::max(1e-9, (hi - lo) / 2);
  std::vector<Eigen::Isometry3d> q;
  for (const auto& s : support) q.push_back(s.common_from_camera * s.own_from_camera.inverse());
  reference_rotation_ = q[0].linear();
  for (int k = 0; k < 3; ++k) translation_[k] = q[0].translation()(k);
  Solve(support, options, options.robust_scale > 0 ? Loss::kHuber : Loss::kNone);
  if (options.outlier_scale > 0) Solve(support, options, Loss::kCauchy);  // from the Huber fit
}

void FittedFrameTransform::Solve(const std::vector<SupportView>& support,
                                 const FrameFitOptions& options, Loss loss) {
  ceres::Problem problem;
  for (size_t n = 0; n < support.size(); ++n) {
    const double x = (support[n].index - center_) / scale_;
    ceres::LossFunction* robust = nullptr;
    if (loss == Loss::kHuber) robust = new ceres::HuberLoss(options.robust_scale);
    if (loss == Loss::kCauchy) robust = new ceres::CauchyLoss(options.outlier_scale);
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<SupportResidual, 6, 9, 9>(
            new SupportResidual(support[n], reference_rotation_, x, options.rotation_weight)),
        robust, rotation_, translation_);
  }
  ceres::Solver::Options solver;
  solver.max_num_iterations = 100;
  solver.linear_solver_type = ceres::DENSE_QR;
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  if (!summary.IsSolutionUsable())
    throw std::runtime_error("registration: the fit did not converge: " + summary.BriefReport());
}

Eigen::Isometry3d FittedFrameTransform::At(double j) const {
  const double x = (j - center_) / scale_;
  Eigen::Vector3d omega, t;
  for (int k = 0; k < 3; ++k) {
    omega(k) = rotation_[k] + rotation_[3 + k] * x + rotation_[6 + k] * x * x;
    t(k) = translation_[k] + translation_[3 + k] * x + translation_[6 + k] * x * x;
  }
  Eigen::Isometry3d q = Eigen::Isometry3d::Identity();
  const double angle = omega.norm();
  q.linear() = (angle > 0 ? Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix()
                          : Eigen::Matrix3d::Identity()) *
               reference_rotation_;
  q.translation() = t;
  return q;
}

Eigen::Matrix4d RegisterPose(const Eigen::Matrix4d& frame_transform,
                             const Eigen::Isometry3d& own_from_camera) {
  return frame_transform * own_from_camera.matrix();  // eq. 6.3
}

}  // namespace novelty::sensors
