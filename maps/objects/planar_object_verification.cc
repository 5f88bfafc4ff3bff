#include "maps/objects/planar_object_verification.h"

#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>
#include <stdexcept>
#include <string>

namespace novelty::objects {

namespace {

// Twice the signed area of a polygon (shoelace): its sign is its orientation.
double SignedArea2(const std::vector<Eigen::Vector2d>& p) {
  double a = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector2d& q = p[(i + 1) % p.size()];
    a += p[i].x() * q.y() - q.x() * p[i].y();
  }
  return a;
}

// A homography is a view of the outline if every outline point maps in front (w > 0) and the
// image keeps the outline's orientation with a non-vanishing area.
bool ViewOfOutline(const Eigen::Matrix3d& h, const std::vector<Eigen::Vector2d>& outline) {
  if (!h.allFinite()) return false;
  std::vector<Eigen::Vector2d> image;
  for (const Eigen::Vector2d& p : outline) {
    const Eigen::Vector3d q = h * p.homogeneous();
    if (!(q.z() > 0.0)) return false;
    image.push_back(q.hnormalized());
  }
  const double before = SignedArea2(outline), after = SignedArea2(image);
  return before != 0.0 && after / before > 0.0 && std::abs(after) >= 2.0;  // ≥ 1 px²
}

}  // namespace

VerifiedHomography VerifyPlanarObject(const std::vector<Eigen::Vector2d>& plane,
                                      const std::vector<cv::Point2f>& pixels,
                                      const std::vector<Eigen::Vector2d>& outline,
                                      const PoseVerificationOptions& options) {
  if (plane.size() != pixels.size())
    throw std::invalid_argument("VerifyPlanarObject: " + std::to_string(plane.size()) +
                                " plane points for " + std::to_string(pixels.size()) + " pixels");
  if (outline.size() < 3)
    throw std::invalid_argument("VerifyPlanarObject: an outline of " +
                                std::to_string(outline.size()) + " points");
  if (!(options.reprojection_px > 0.0) || options.min_inliers < 4 || options.max_iterations < 1)
    throw std::invalid_argument(
        "PoseVerificationOptions: reprojection_px > 0, min_inliers >= 4, "
        "max_iterations >= 1");
  std::vector<cv::Point2f> from, to;
  std::vector<int> given;
  for (std::size_t i = 0; i < plane.size(); ++i) {
    if (!plane[i].allFinite()) continue;
    from.emplace_back(float(plane[i].x()), float(plane[i].y()));
    to.push_back(pixels[i]);
    given.push_back(int(i));
  }
  VerifiedHomography out;
  out.pairs = int(from.size());
  if (out.pairs < options.min_inliers) return out;
  cv::Mat mask;
  const cv::Mat h = cv::findHomography(from, to, cv::RANSAC, options.reprojection_px, mask,
                                       options.max_iterations, 0.999);
  if (h.empty()) return out;
  cv::cv2eigen(h, out.image_from_plane);
  for (int i = 0; i < mask.rows; ++i)
    if (mask.at<uchar>(i)) out.inlier_pairs.push_back(given[std::size_t(i)]);
  out.inliers = int(out.inlier_pairs.size());
  out.verified = out.inliers >= options.min_inliers && ViewOfOutline(out.image_from_plane, outline);
  if (out.inliers < options.min_inliers) out.inlier_pairs.clear();
  return out;
}

std::vector<cv::Point2f> MapOutline(const Eigen::Matrix3d& image_from_plane,
                                    const std::vector<Eigen::Vector2d>& outline) {
  std::vector<cv::Point2f> image;
  for (const Eigen::Vector2d& p : outline) {
    const Eigen::Vector2d q = (image_from_plane * p.homogeneous()).hnormalized();
    image.emplace_back(float(q.x()), float(q.y()));
  }
  return image;
}

}  // namespace novelty::objects
