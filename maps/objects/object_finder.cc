#include "maps/objects/object_finder.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "maps/objects/planar_object_verification.h"

namespace novelty::objects {

namespace {

// The keypoints that speak for `object`: its agreeing pairs when verified, else its matches.
std::vector<cv::Point2f> Evidence(const FrameRecognition& r, const FeatureDatabase& database,
                                  int object, const VerifiedPose& pose) {
  std::vector<cv::Point2f> points;
  if (pose.verified) {
    for (int i : pose.inlier_pairs) points.push_back(r.keypoints[r.matches[i].candidate].pt);
    return points;
  }
  for (const RatioMatch& m : r.matches)
    if (database.MostProbableObject(m.reference) == object)
      points.push_back(r.keypoints[std::size_t(m.candidate)].pt);
  return points;
}

std::vector<cv::Point2f> BoxOf(const std::vector<cv::Point2f>& points) {
  const cv::Rect2f b = cv::boundingRect(points);
  return {b.tl(), {b.x + b.width, b.y}, b.br(), {b.x, b.y + b.height}};
}

// The median (per axis) of the points' back-projections where depth is known; NaN if nowhere.
Eigen::Vector3d Place(const std::vector<cv::Point2f>& points, const cv::Mat& depth,
                      const core::PinholeCamera& camera) {
  std::vector<double> axis[3];
  for (const cv::Point2f& p : points) {
    const int u = int(std::lround(p.x)), v = int(std::lround(p.y));
    if (depth.empty() || u < 0 || v < 0 || u >= depth.cols || v >= depth.rows) continue;
    const float d = depth.at<float>(v, u);
    if (!(d > 0.f) || !std::isfinite(d)) continue;
    const Eigen::Vector3d q = camera.Unproject(p.x, p.y, d);
    for (int a = 0; a < 3; ++a) axis[a].push_back(q[a]);
  }
  Eigen::Vector3d place = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  if (axis[0].empty()) return place;
  for (int a = 0; a < 3; ++a) {
    auto mid = axis[a].begin() + std::ptrdiff_t(axis[a].size() / 2);
    std::nth_element(axis[a].begin(), mid, axis[a].end());
    place[a] = *mid;
  }
  return place;
}

// Better evidence first: verified, then more agreeing places, then more matches, then the lower
// class (deterministic).
bool Better(const FoundObject& a, const FoundObject& b) {
  if (a.verified != b.verified) return a.verified;
  if (a.inliers != b.inliers) return a.inliers > b.inliers;
  if (a.matches != b.matches) return a.matches > b.matches;
  return a.object < b.object;
}

}  // namespace

std::vector<FoundObject> FindObjects(const FrameFeatures& features, const cv::Mat& depth,
                                     const FeatureDatabase& database,
                                     const core::PinholeCamera& camera,
                                     const ObjectFinderOptions& options) {
  if (options.min_matches < 1)
    throw std::invalid_argument("ObjectFinderOptions: min_matches must be >= 1, got " +
                                std::to_string(options.min_matches));
  // The evidence of a verified object is read from its inlier pairs as indices of the ratio
  // matches, which verify_nearest's pairs are not.
  if (options.recognition.verify_nearest != 0)
    throw std::invalid_argument("ObjectFinderOptions: verify_nearest must be 0");
  if (!depth.empty() &&
      (depth.type() != CV_32FC1 || depth.cols != camera.width || depth.rows != camera.height))
    throw std::invalid_argument("FindObjects: the depth image is not CV_32F of the camera's size");
  const FrameRecognition r = MatchObjects(features, database, camera, options.recognition);
  std::map<std::string, FoundObject> best;  // per name
  for (int k = 0; k < database.objects(); ++k) {
    const ObjectEvidence& e = r.per_object[std::size_t(k)];
    std::vector<int> of_k;
    for (std::size_t i = 0; i < r.matches.size(); ++i)
      if (database.MostProbableObject(r.matches[i].reference) == k) of_k.push_back(int(i));
    const int places = DistinctPlaces(r.matches, of_k, r.keypoints,
                                      options.recognition.verification.reprojection_px);
    if (!e.pose.verified && places < options.min_matches) continue;
    FoundObject f;
    f.object = k;
    f.name = database.DisplayName(k);
    f.matches = places;
    f.verified = e.pose.verified;
    f.inliers = e.pose.verified ? e.pose.inliers : 0;
    f.T_cam_object = e.pose.T_cam_object;
    const std::vector<cv::Point2f> evidence = Evidence(r, database, k, e.pose);
    f.outline = f.verified && database.Info(k).planar()
                    ? MapOutline(e.pose.image_from_plane, database.Info(k).outline)
                    : BoxOf(evidence);
    f.place = Place(evidence, depth, camera);
    auto [it, added] = best.emplace(f.name, f);
    if (!added && Better(f, it->second)) it->second = f;
  }
  std::vector<FoundObject> found;
  for (auto& [name, f] : best) found.push_back(std::move(f));
  std::sort(found.begin(), found.end(), Better);
  return found;
}

}  // namespace novelty::objects
