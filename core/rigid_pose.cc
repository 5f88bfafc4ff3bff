#include "core/rigid_pose.h"

#include <cmath>
#include <stdexcept>

namespace novelty::core {

bool IsRigid(const Eigen::Isometry3d& T, double tolerance) {
  const Eigen::Matrix3d r = T.linear();
  return r.allFinite() && T.translation().allFinite() &&
         (r.transpose() * r - Eigen::Matrix3d::Identity()).norm() < tolerance &&
         std::abs(r.determinant() - 1.0) < tolerance;
}

Eigen::Isometry3d LookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target) {
  const Eigen::Vector3d z = target - eye;
  if (z.norm() < 1e-12) throw std::invalid_argument("LookAt: eye and target coincide");
  const Eigen::Vector3d zc = z.normalized();
  const Eigen::Vector3d xc = zc.cross(Eigen::Vector3d::UnitZ());  // right = forward × up
  if (xc.norm() < 1e-9) throw std::invalid_argument("LookAt: view direction is vertical");
  Eigen::Matrix3d r;
  r.col(0) = xc.normalized();
  r.col(2) = zc;
  r.col(1) = zc.cross(r.col(0));  // down
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = r;
  t.translation() = eye;
  return t;
}

}  // namespace novelty::core
