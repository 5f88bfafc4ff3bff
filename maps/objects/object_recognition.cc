#include "maps/objects/object_recognition.h"

#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "maps/objects/planar_object_verification.h"

namespace novelty::objects {

int DistinctPlaces(const std::vector<RatioMatch>& matches, const std::vector<int>& agreeing,
                   const std::vector<cv::KeyPoint>& keypoints, double tolerance_px) {
  std::vector<cv::Point2f> counted;
  std::vector<int> references;
  const float merge2 = float(4.0 * tolerance_px * tolerance_px);
  for (int i : agreeing) {
    const RatioMatch& m = matches[std::size_t(i)];
    const cv::Point2f& p = keypoints[std::size_t(m.candidate)].pt;
    if (std::find(references.begin(), references.end(), m.reference) != references.end() ||
        std::any_of(counted.begin(), counted.end(), [&](const cv::Point2f& q) {
          const cv::Point2f d = p - q;
          return d.dot(d) <= merge2;
        }))
      continue;
    counted.push_back(p);
    references.push_back(m.reference);
  }
  return int(counted.size());
}

namespace {

// The pose of a verified planar object in the camera, from its inlier pairs (OpenCV's IPPE, made
// for points on a plane): the photo's plane is the object's frame, z = 0.
Eigen::Isometry3d PlanarPose(const std::vector<Eigen::Vector2d>& plane,
                             const std::vector<cv::Point2f>& pixels,
                             const std::vector<int>& inliers, const core::PinholeCamera& camera) {
  std::vector<cv::Point3f> points;
  std::vector<cv::Point2f> image;
  for (int i : inliers) {
    points.emplace_back(float(plane[std::size_t(i)].x()), float(plane[std::size_t(i)].y()), 0.f);
    image.push_back(pixels[std::size_t(i)]);
  }
  const cv::Matx33d k(camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1);
  cv::Mat rvec, tvec;
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  if (!cv::solvePnP(points, image, k, cv::noArray(), rvec, tvec, false, cv::SOLVEPNP_IPPE))
    return t;
  cv::Mat r;
  cv::Rodrigues(rvec, r);
  Eigen::Matrix3d re;
  Eigen::Vector3d te;
  cv::cv2eigen(r, re);
  cv::cv2eigen(tvec, te);
  t.linear() = re;
  t.translation() = te;
  return t;
}

// VerifyObjectMatches for an object learnt from a photo: a homography instead of a 3-D pose.
VerifiedPose VerifyPlanarMatches(const FeatureDatabase& database,
                                 const std::vector<RatioMatch>& matches,
                                 const std::vector<cv::KeyPoint>& keypoints, int object,
                                 const core::PinholeCamera& camera,
                                 const PoseVerificationOptions& options) {
  std::vector<Eigen::Vector2d> plane;
  std::vector<cv::Point2f> pixels;
  std::vector<int> used;
  for (std::size_t i = 0; i < matches.size(); ++i) {
    const RatioMatch& m = matches[i];
    if (database.MostProbableObject(m.reference) != object) continue;
    plane.push_back(database.Position(m.reference).head<2>());
    pixels.push_back(keypoints.at(std::size_t(m.candidate)).pt);
    used.push_back(int(i));
  }
  const VerifiedHomography h =
      VerifyPlanarObject(plane, pixels, database.Info(object).outline, options);
  VerifiedPose pose;
  pose.pairs = h.pairs;
  pose.inliers = h.inliers;
  pose.image_from_plane = h.image_from_plane;
  for (int i : h.inlier_pairs) pose.inlier_pairs.push_back(used[std::size_t(i)]);
  if (!h.verified) return pose;
  pose.inliers = DistinctPlaces(matches, pose.inlier_pairs, keypoints, options.reprojection_px);
  pose.verified = pose.inliers >= options.min_inliers;
  if (pose.verified) pose.T_cam_object = PlanarPose(plane, pixels, h.inlier_pairs, camera);
  return pose;
}

}  // namespace

VerifiedPose VerifyObjectMatches(const FeatureDatabase& database,
                                 const std::vector<RatioMatch>& matches,
                                 const std::vector<cv::KeyPoint>& keypoints, int object,
                                 const core::PinholeCamera& camera,
                                 const PoseVerificationOptions& options) {
  if (database.Info(object).planar())
    return VerifyPlanarMatches(database, matches, keypoints, object, camera, options);
  std::vector<Eigen::Vector3d> places;
  std::vector<cv::Point2f> pixels;
  std::vector<int> used;  // per pair, its index in `matches`
  for (std::size_t i = 0; i < matches.size(); ++i) {
    const RatioMatch& m = matches[i];
    if (database.MostProbableObject(m.reference) != object) continue;
    places.push_back(database.Position(m.reference));
    pixels.push_back(keypoints.at(std::size_t(m.candidate)).pt);
    used.push_back(int(i));
  }
  VerifiedPose pose = VerifyObjectPose(places, pixels, camera, options);
  for (int& i : pose.inlier_pairs) i = used[std::size_t(i)];
  if (!pose.verified) return pose;
  pose.inliers = DistinctPlaces(matches, pose.inlier_pairs, keypoints, options.reprojection_px);
  if (pose.inliers < options.min_inliers) {
    pose.verified = false;
    pose.T_cam_object = Eigen::Isometry3d::Identity();
  }
  return pose;
}

FrameFeatures ExtractFrameFeatures(const cv::Mat& grey, cv::Feature2D& extractor) {
  FrameFeatures f;
  extractor.detectAndCompute(grey, cv::noArray(), f.keypoints, f.descriptors);
  if (!f.keypoints.empty() && f.descriptors.type() != CV_32F)
    f.descriptors.convertTo(f.descriptors, CV_32F);
  return f;
}

FrameFeatures ExtractFrameFeatures(const cv::Mat& grey, cv::Feature2D& extractor,
                                   const cv::Mat& depth, const core::PinholeCamera& camera) {
  // A depth of another size would give each keypoint the depth of another place.
  if (!depth.empty() && depth.size() != grey.size())
    throw std::invalid_argument("ExtractFrameFeatures: the depth image is " +
                                std::to_string(depth.cols) + "x" + std::to_string(depth.rows) +
                                ", the grey image " + std::to_string(grey.cols) + "x" +
                                std::to_string(grey.rows));
  FrameFeatures f = ExtractFrameFeatures(grey, extractor);
  if (!depth.empty()) f.metric_sizes = MetricSizes(f.keypoints, depth, camera);
  return f;
}

FeatureDatabase::Recognition KeepConsistentMatches(const FeatureDatabase& database,
                                                   const FrameFeatures& features,
                                                   const KeypointConsistencyOptions& options,
                                                   const std::vector<RatioMatch>& matches) {
  if (options.enabled) CheckKeypointConsistencyOptions(options);
  if (!features.metric_sizes.empty() && features.metric_sizes.size() != features.keypoints.size())
    throw std::invalid_argument(
        "KeepConsistentMatches: " + std::to_string(features.metric_sizes.size()) +
        " metric sizes for " + std::to_string(features.keypoints.size()) + " keypoints");
  std::vector<RatioMatch> kept;
  for (const RatioMatch& match : matches) {
    const std::size_t c = std::size_t(match.candidate);
    const double size = features.metric_sizes.empty() ? std::nan("") : features.metric_sizes.at(c);
    if (ConsistentKeypoint(database.Keypoint(match.reference), features.keypoints.at(c), size,
                           options))
      kept.push_back(match);
  }
  return database.Tally(std::move(kept));
}

FrameRecognition MatchObjects(const FrameFeatures& features, const FeatureDatabase& database,
                              const core::PinholeCamera& camera,
                              const ObjectRecognitionOptions& options) {
  if (options.verify_nearest < 0)
    throw std::invalid_argument("ObjectRecognitionOptions: verify_nearest must be >= 0, got " +
                                std::to_string(options.verify_nearest));
  FrameRecognition r;
  r.keypoints = features.keypoints;
  const bool any = !r.keypoints.empty();
  if (any && database.features() > 0 && features.descriptors.cols != database.descriptors().cols)
    throw std::invalid_argument("MatchObjects: the frame's descriptors have width " +
                                std::to_string(features.descriptors.cols) + ", the database's " +
                                std::to_string(database.descriptors().cols));
  FeatureDatabase::Recognition m =
      database.Match(any ? features.descriptors : cv::Mat(), options.match_ratio,
                     options.distinct_second && any ? &r.keypoints : nullptr);
  if (options.consistency.enabled)
    m = KeepConsistentMatches(database, features, options.consistency, m.matches);
  r.matches = m.matches;
  // The pairs verification sorts out: the ratio matches, or each feature's nearest keypoints.
  const std::vector<RatioMatch> nearest =
      options.verify && options.verify_nearest > 0 && any && database.features() > 0
          ? NearestMatches(database.descriptors(), features.descriptors, options.verify_nearest)
          : std::vector<RatioMatch>();
  const std::vector<RatioMatch>& pairs = options.verify_nearest > 0 ? nearest : r.matches;
  r.per_object.resize(std::size_t(database.objects()));
  for (int k = 0; k < database.objects(); ++k) {
    ObjectEvidence& e = r.per_object[std::size_t(k)];
    e.matches = m.matches_per_object[std::size_t(k)];
    if (options.verify && (e.matches > 0 || options.verify_nearest > 0))
      e.pose = VerifyObjectMatches(database, pairs, r.keypoints, k, camera, options.verification);
  }
  return r;
}

FrameRecognition RecognizeObjects(const cv::Mat& grey, const cv::Mat& depth,
                                  cv::Feature2D& extractor, const FeatureDatabase& database,
                                  const core::PinholeCamera& camera,
                                  const ObjectRecognitionOptions& options) {
  return MatchObjects(ExtractFrameFeatures(grey, extractor, depth, camera), database, camera,
                      options);
}

}  // namespace novelty::objects
