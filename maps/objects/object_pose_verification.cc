#include "maps/objects/object_pose_verification.h"

#include <cmath>
#include <memory>
#include <opengv/absolute_pose/CentralAbsoluteAdapter.hpp>
#include <opengv/absolute_pose/methods.hpp>
#include <opengv/sac/Ransac.hpp>
#include <opengv/sac_problems/absolute_pose/AbsolutePoseSacProblem.hpp>
#include <stdexcept>
#include <string>

namespace novelty::objects {

VerifiedPose VerifyObjectPose(const std::vector<Eigen::Vector3d>& points_object,
                              const std::vector<cv::Point2f>& pixels,
                              const core::PinholeCamera& camera,
                              const PoseVerificationOptions& options) {
  if (points_object.size() != pixels.size())
    throw std::invalid_argument("VerifyObjectPose: " + std::to_string(points_object.size()) +
                                " points for " + std::to_string(pixels.size()) + " pixels");
  if (!(options.reprojection_px > 0.0) || options.min_inliers < 4 || options.max_iterations < 1)
    throw std::invalid_argument(
        "PoseVerificationOptions: reprojection_px > 0, min_inliers >= 4, "
        "max_iterations >= 1");
  opengv::bearingVectors_t bearings;
  opengv::points_t points;
  std::vector<int> given;  // per pair used, its index among those given
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    if (!points_object[i].allFinite()) continue;
    bearings.push_back(camera.RayCam(pixels[i].x, pixels[i].y).normalized());
    points.push_back(points_object[i]);
    given.push_back(int(i));
  }
  VerifiedPose out;
  out.pairs = int(points.size());
  if (out.pairs < options.min_inliers) return out;
  opengv::absolute_pose::CentralAbsoluteAdapter adapter(bearings, points);
  using Problem = opengv::sac_problems::absolute_pose::AbsolutePoseSacProblem;
  auto problem = std::make_shared<Problem>(adapter, Problem::KNEIP, /*randomSeed=*/false);
  opengv::sac::Ransac<Problem> ransac;
  ransac.sac_model_ = problem;
  // OpenGV's error is 1 − cos(angle between the bearing and the reprojected ray): a pixel
  // error e at the focal length f is the angle atan(e / f).
  ransac.threshold_ = 1.0 - std::cos(std::atan(options.reprojection_px / camera.fx));
  ransac.max_iterations_ = options.max_iterations;
  if (!ransac.computeModel()) return out;
  if (int(ransac.inliers_.size()) < options.min_inliers) {
    out.inliers = int(ransac.inliers_.size());
    return out;
  }
  // RANSAC's pose is one minimal sample's: refined on all its inliers (Levenberg–Marquardt on
  // the bearing errors), it uses every agreeing pair. OpenGV's model: the camera's rotation and
  // position in the object's frame.
  adapter.setR(ransac.model_coefficients_.block<3, 3>(0, 0));
  adapter.sett(ransac.model_coefficients_.col(3));
  opengv::transformation_t m = opengv::absolute_pose::optimize_nonlinear(adapter, ransac.inliers_);
  // The pairs that agree with the refined pose, by the same error RANSAC used; RANSAC's own pose
  // and inliers if the refinement agrees with fewer (or failed).
  std::vector<int> agreeing;
  if (m.allFinite()) problem->selectWithinDistance(m, ransac.threshold_, agreeing);
  if (agreeing.size() < ransac.inliers_.size()) {
    m = ransac.model_coefficients_;
    agreeing = ransac.inliers_;
  }
  for (int i : agreeing) out.inlier_pairs.push_back(given[std::size_t(i)]);
  out.inliers = int(out.inlier_pairs.size());
  out.verified = out.inliers >= options.min_inliers;
  if (out.verified) {
    Eigen::Isometry3d T_object_cam = Eigen::Isometry3d::Identity();
    T_object_cam.linear() = m.block<3, 3>(0, 0);
    T_object_cam.translation() = m.col(3);
    out.T_cam_object = T_object_cam.inverse();
  }
  return out;
}

}  // namespace novelty::objects
