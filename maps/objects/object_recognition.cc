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

FrameFeatures ExtractFrameFeatures(const cv::Mat& grey, cv::Feature2D& extractor) {
  FrameFeatures f;
  extractor.detectAndCompute(grey, cv::noArray(), f.keypoints, f.descriptors);
  if (!f.keypoints.empty() && f.descriptors.type() != CV_32F)
    f.descriptors.convertTo(f.descriptors, CV_32F);
  return f;
}

FrameRecognition MatchObjects(const FrameFeatures& features, const FeatureDatabase& database,
                              const core::PinholeCamera& camera,
                              const ObjectRecognitionOptions& options) {
  FrameRecognition r;
  r.keypoints = features.keypoints;
  const bool any = !r.keypoints.empty();
  if (any && database.features() > 0 && features.descriptors.cols != database.descriptors().cols)
    throw std::invalid_argument("MatchObjects: the frame's descriptors have width " +
                                std::to_string(features.descriptors.cols) + ", the database's " +
                                std::to_string(database.descriptors().cols));
  const FeatureDatabase::Recognition m =
      database.Match(any ? features.descriptors : cv::Mat(), options.match_ratio,
                     options.distinct_second && any ? &r.keypoints : nullptr);
  r.matches = m.matches;
  r.per_object.resize(std::size_t(database.objects()));
  for (int k = 0; k < database.objects(); ++k) {
    ObjectEvidence& e = r.per_object[std::size_t(k)];
    e.matches = m.matches_per_object[std::size_t(k)];
    if (options.verify && e.matches > 0)
      e.pose =
          VerifyObjectMatches(database, r.matches, r.keypoints, k, camera, options.verification);
  }
  return r;
}

FrameRecognition RecognizeObjects(const cv::Mat& grey, cv::Feature2D& extractor,
                                  const FeatureDatabase& database,
                                  const core::PinholeCamera& camera,
                                  const ObjectRecognitionOptions& options) {
  return MatchObjects(ExtractFrameFeatures(grey, extractor), database, camera, options);
}

}  // namespace novelty::objects
