#include "maps/objects/object_recognition.h"

#include <stdexcept>
#include <string>

namespace novelty::objects {

VerifiedPose VerifyObjectMatches(const FeatureDatabase& database,
                                 const std::vector<RatioMatch>& matches,
                                 const std::vector<cv::KeyPoint>& keypoints, int object,
                                 const core::PinholeCamera& camera,
                                 const PoseVerificationOptions& options) {
  std::vector<Eigen::Vector3d> places;
  std::vector<cv::Point2f> pixels;
  for (const RatioMatch& m : matches) {
    if (database.MostProbableObject(m.reference) != object) continue;
    places.push_back(database.Position(m.reference));
    pixels.push_back(keypoints.at(std::size_t(m.candidate)).pt);
  }
  return VerifyObjectPose(places, pixels, camera, options);
}

FrameRecognition RecognizeObjects(const cv::Mat& grey, cv::Feature2D& extractor,
                                  const FeatureDatabase& database, double match_ratio,
                                  const core::PinholeCamera& camera,
                                  const PoseVerificationOptions* verification) {
  FrameRecognition r;
  cv::Mat descriptors;
  extractor.detectAndCompute(grey, cv::noArray(), r.keypoints, descriptors);
  if (!r.keypoints.empty() && descriptors.type() != CV_32F)
    descriptors.convertTo(descriptors, CV_32F);
  if (!r.keypoints.empty() && database.features() > 0 &&
      descriptors.cols != database.descriptors().cols)
    throw std::invalid_argument("RecognizeObjects: the extractor gives descriptors of width " +
                                std::to_string(descriptors.cols) + ", the database holds " +
                                std::to_string(database.descriptors().cols));
  const FeatureDatabase::Recognition m =
      database.Match(r.keypoints.empty() ? cv::Mat() : descriptors, match_ratio);
  r.matches = m.matches;
  r.per_object.resize(std::size_t(database.objects()));
  for (int k = 0; k < database.objects(); ++k) {
    ObjectEvidence& e = r.per_object[std::size_t(k)];
    e.matches = m.matches_per_object[std::size_t(k)];
    if (verification && e.matches > 0)
      e.pose = VerifyObjectMatches(database, r.matches, r.keypoints, k, camera, *verification);
  }
  return r;
}

}  // namespace novelty::objects
