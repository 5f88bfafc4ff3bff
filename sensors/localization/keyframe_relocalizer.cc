#include "sensors/localization/keyframe_relocalizer.h"

#include <opencv2/features2d.hpp>
#include <vector>

#include "sensors/localization/opencv_pose.h"

namespace novelty::sensors {
namespace {

struct RelocalizerKeyframe {
  std::vector<cv::Point3f> world;
  cv::Mat descriptors;  // ORB, one row per world point
};

}  // namespace

struct KeyframeRelocalizer::Impl {
  KeyframeRelocalizerOptions options;
  cv::Ptr<cv::ORB> orb;
  std::vector<RelocalizerKeyframe> keyframes;
};

KeyframeRelocalizer::KeyframeRelocalizer(const KeyframeRelocalizerOptions& options)
    : impl_(std::make_unique<Impl>(Impl{options, cv::ORB::create(options.orb_features), {}})) {}
KeyframeRelocalizer::~KeyframeRelocalizer() = default;
KeyframeRelocalizer::KeyframeRelocalizer(KeyframeRelocalizer&&) noexcept = default;
KeyframeRelocalizer& KeyframeRelocalizer::operator=(KeyframeRelocalizer&&) noexcept = default;

size_t KeyframeRelocalizer::size() const {
  return impl_->keyframes.size();
}

bool KeyframeRelocalizer::Add(const StereoPair& pair, const cv::Mat& reference_grey,
                              const cv::Mat& other_grey,
                              const Eigen::Isometry3d& world_from_camera) {
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  impl_->orb->detectAndCompute(reference_grey, cv::noArray(), keypoints, descriptors);
  std::vector<cv::Point2f> px;
  for (const cv::KeyPoint& k : keypoints) px.push_back(k.pt);
  const auto points =
      TriangulateFeatures(pair, reference_grey, other_grey, px, impl_->options.stereo);
  RelocalizerKeyframe k;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!points[i]) continue;
    const Eigen::Vector3d w = world_from_camera * *points[i];
    k.world.emplace_back(float(w.x()), float(w.y()), float(w.z()));
    k.descriptors.push_back(descriptors.row(int(i)));
  }
  if (int(k.world.size()) < impl_->options.min_inliers) return false;
  impl_->keyframes.push_back(std::move(k));
  if (impl_->keyframes.size() > impl_->options.max_keyframes)
    impl_->keyframes.erase(impl_->keyframes.begin());
  return true;
}

std::optional<Eigen::Isometry3d> KeyframeRelocalizer::Relocalize(const StereoPair& pair,
                                                                 const cv::Mat& grey) const {
  const KeyframeRelocalizerOptions& o = impl_->options;
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  impl_->orb->detectAndCompute(grey, cv::noArray(), keypoints, descriptors);
  if (keypoints.size() < 8) return std::nullopt;
  cv::BFMatcher matcher(cv::NORM_HAMMING);
  std::optional<Eigen::Isometry3d> best;
  int best_inliers = o.min_inliers - 1;
  const cv::Mat k = CameraMatrix(pair.reference_camera);
  for (const RelocalizerKeyframe& kf : impl_->keyframes) {
    std::vector<std::vector<cv::DMatch>> knn;
    matcher.knnMatch(descriptors, kf.descriptors, knn, 2);
    std::vector<cv::Point3f> object;
    std::vector<cv::Point2f> image;
    for (const auto& m : knn) {
      if (m.size() < 2 || m[0].distance > o.ratio * m[1].distance) continue;
      object.push_back(kf.world[m[0].trainIdx]);
      image.push_back(keypoints[m[0].queryIdx].pt);
    }
    if (int(object.size()) < o.min_inliers) continue;
    cv::Mat rvec, tvec;
    std::vector<int> inliers;
    if (!cv::solvePnPRansac(object, image, k, cv::noArray(), rvec, tvec, false, o.ransac_iterations,
                            float(o.reprojection_px), 0.99, inliers))
      continue;
    if (int(inliers.size()) <= best_inliers) continue;
    best_inliers = int(inliers.size());
    best = WorldFromRvecTvec(rvec, tvec);
  }
  return best;
}

}  // namespace novelty::sensors
