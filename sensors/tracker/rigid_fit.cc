#include "sensors/tracker/rigid_fit.h"

#include <Eigen/SVD>
#include <cmath>

namespace novelty::sensors {
namespace {

std::optional<RigidFitResult> Fail(std::string* why, const std::string& reason) {
  if (why) *why = reason;
  return std::nullopt;
}

}  // namespace

std::optional<RigidFitResult> FitRigid(const std::vector<Eigen::Vector3d>& model,
                                       const std::vector<Eigen::Vector3d>& measured,
                                       const std::vector<double>& weights, std::string* why) {
  const size_t n = model.size();
  if (measured.size() != n || (!weights.empty() && weights.size() != n))
    return Fail(why, "point sets of different sizes");
  double w_sum = 0.0;
  int used = 0;
  Eigen::Vector3d model_mean = Eigen::Vector3d::Zero(), measured_mean = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < n; ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    if (!(w >= 0.0) || !model[i].allFinite() || !measured[i].allFinite())
      return Fail(why, "point " + std::to_string(i) + " has a negative weight or is not finite");
    if (w == 0.0) continue;
    w_sum += w;
    ++used;
    model_mean += w * model[i];
    measured_mean += w * measured[i];
  }
  if (used < 3) return Fail(why, std::to_string(used) + " weighted points (3 needed)");
  model_mean /= w_sum;
  measured_mean /= w_sum;

  // eq. 3.1 / 3.4: weighted inertia matrix of the centred sets, A = Σ w P̂' P'ᵀ.
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  double spread = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    if (w == 0.0) continue;
    const Eigen::Vector3d p = model[i] - model_mean;
    a += w * (measured[i] - measured_mean) * p.transpose();
    spread += w * p.squaredNorm();
  }
  // A = U Σ Vᵀ here is the transpose of the thesis's convention (it forms Σ P̂' P'ᵀ, we solve for
  // R in measured = R·model), so R = U Vᵀ — eq. 3.2 with the roles of U and V exchanged.
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector3d s = svd.singularValues();
  if (s(1) <= 1e-9 * spread) return Fail(why, "model points are collinear");
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  RigidFitResult result;
  if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0) {
    d(2, 2) = -1.0;
    result.reflection_corrected = true;
  }
  const Eigen::Matrix3d r = svd.matrixU() * d * svd.matrixV().transpose();
  result.transform.linear() = r;
  result.transform.translation() = measured_mean - r * model_mean;  // eq. 3.3
  double sq = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    sq += w * (measured[i] - result.transform * model[i]).squaredNorm();
  }
  result.rms = std::sqrt(sq / w_sum);
  return result;
}

}  // namespace novelty::sensors
