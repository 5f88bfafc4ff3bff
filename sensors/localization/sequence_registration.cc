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

// Residual of one support view: the rotation angle-axis of Q(j_n)ᵀ·Q_n and the translation gap,
// the translation in metres and the rotation in radians weighted by `rotation_weight` (m/rad).
struct SupportResidual {
  SupportResidual(const Eigen::Isometry3d& q, const Eigen::Matrix3d& reference, double x,
                  double rotation_weight)
      : q_(q), reference_(reference), x_(x), w_(rotation_weight) {}

  template <typename T>
  bool operator()(const T* rotation, const T* translation, T* residual) const {
    // ω(x) = a + b·x + c·x²; Q_R(x) = exp([ω]×)·R̄
    T omega[3], r_delta[9];
    for (int k = 0; k < 3; ++k)
      omega[k] = rotation[k] + rotation[3 + k] * T(x_) + rotation[6 + k] * T(x_ * x_);
    ceres::AngleAxisToRotationMatrix(omega, r_delta);  // column-major
    // E = Q_Rᵀ·Q_n,R = R̄ᵀ·Δᵀ·Q_n,R ; residual = log(E)
    T e[9];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        T sum = T(0);
        for (int k = 0; k < 3; ++k) {
          // (Δ·R̄)ᵀ(r,k) = (Δ·R̄)(k,r) = Σ_m Δ(k,m) R̄(m,r)
          T dr = T(0);
          for (int m = 0; m < 3; ++m) dr += r_delta[m * 3 + k] * T(reference_(m, r));
          sum += dr * T(q_.linear()(k, c));
        }
        e[c * 3 + r] = sum;  // column-major for ceres
      }
    T angle_axis[3];
    ceres::RotationMatrixToAngleAxis(e, angle_axis);
    for (int k = 0; k < 3; ++k) {
      residual[k] = T(w_) * angle_axis[k];
      residual[3 + k] = translation[k] + translation[3 + k] * T(x_) +
                        translation[6 + k] * T(x_ * x_) - T(q_.translation()(k));
    }
    return true;
  }

  Eigen::Isometry3d q_;
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

FittedFrameTransform::FittedFrameTransform(const std::vector<SupportView>& support) {
  CheckSupport(support);
  double lo = support[0].index, hi = lo;
  for (const auto& s : support) lo = std::min(lo, s.index), hi = std::max(hi, s.index);
  center_ = (lo + hi) / 2;
  scale_ = std::max(1e-9, (hi - lo) / 2);
  std::vector<Eigen::Isometry3d> q;
  for (const auto& s : support) q.push_back(s.common_from_camera * s.own_from_camera.inverse());
  reference_rotation_ = q[0].linear();
  ceres::Problem problem;
  for (size_t n = 0; n < support.size(); ++n) {
    const double x = (support[n].index - center_) / scale_;
    // 1 rad ~ 1 m: rotation and translation errors of a room-sized scene weigh alike.
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<SupportResidual, 6, 9, 9>(
                                 new SupportResidual(q[n], reference_rotation_, x, 1.0)),
                             nullptr, rotation_, translation_);
  }
  for (int k = 0; k < 3; ++k) translation_[k] = q[0].translation()(k);
  ceres::Solver::Options options;
  options.max_num_iterations = 100;
  options.linear_solver_type = ceres::DENSE_QR;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
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
