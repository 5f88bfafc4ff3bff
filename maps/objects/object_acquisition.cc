#include "maps/objects/object_acquisition.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/nearest_pixel.h"
#include "maps/objects/feature_extractor.h"

namespace novelty::objects {
namespace {

ObjectLearnerOptions LearnerOptionsFor(const ObjectAcquisitionOptions& o) {
  ObjectLearnerOptions l = o.learner;
  l.window_per_scale = DescriptorWindowPerSize(o.extractor);  // window per keypoint size
  l.size_per_scale = 1.0;
  l.window_angle_sign = DescriptorWindowAngleSign(o.extractor);
  return l;
}

const ObjectAcquisitionOptions& Checked(const ObjectAcquisitionOptions& o) {
  // Every option is checked here, so that bad ones fail when the map is made or loaded, not at
  // every frame.
  if (!(o.relative_descriptor_change > 0.0))
    throw std::invalid_argument("ObjectAcquisitionOptions: relative_descriptor_change must be > 0");
  if (!(o.focus.xi >= 0.0 && std::isfinite(o.focus.xi)) || o.focus.morphology_size < 0)
    throw std::invalid_argument(
        "ObjectAcquisitionOptions: xi must be finite and >= 0, "
        "morphology_size >= 0");
  if (!(o.change.min_relative_difference >= 0.0) ||
      !(o.change.min_known_share >= 0.0 && o.change.min_known_share <= 1.0))
    throw std::invalid_argument(
        "ObjectAcquisitionOptions: min_relative_difference must be >= 0, "
        "min_known_share in [0, 1]");
  DescriptorWidth(o.extractor);  // throws for a value that names no extractor
  return o;
}

void CheckPlane(const cv::Mat& m, int type, const core::PinholeCamera& camera, const char* name,
                bool may_be_empty) {
  if (may_be_empty && m.empty()) return;
  if (m.type() != type || m.cols != camera.width || m.rows != camera.height)
    throw std::invalid_argument(std::string("ObjectAcquisition::Process: ") + name + " must be " +
                                (type == CV_8UC3    ? "CV_8UC3"
                                 : type == CV_32FC2 ? "CV_32FC2"
                                                    : "CV_32FC1") +
                                " of " + std::to_string(camera.width) + "x" +
                                std::to_string(camera.height) + ", is " + std::to_string(m.cols) +
                                "x" + std::to_string(m.rows) + " of type " +
                                std::to_string(m.type()));
}

}  // namespace

ObjectAcquisition::ObjectAcquisition(const ObjectAcquisitionOptions& options)
    : options_(Checked(options)),
      extractor_(CreateFeatureExtractor(options.extractor)),
      learner_(LearnerOptionsFor(options)) {}

AcquisitionStep ObjectAcquisition::Process(const cv::Mat& rgb, const cv::Mat& depth,
                                           const cv::Mat& surprise, const cv::Mat& expected_depth,
                                           const core::PinholeCamera& camera,
                                           const Eigen::Isometry3d& T_world_cam) {
  CheckPlane(rgb, CV_8UC3, camera, "rgb", false);
  CheckPlane(depth, CV_32FC1, camera, "depth", false);
  CheckPlane(surprise, CV_32FC1, camera, "surprise", false);
  CheckPlane(expected_depth, expected_depth.type() == CV_32FC2 ? CV_32FC2 : CV_32FC1, camera,
             "expected depth", true);
  if (!T_world_cam.matrix().allFinite())
    throw std::invalid_argument("ObjectAcquisition::Process: the pose is not finite");

  AcquisitionStep step;
  step.focus = FindFocusOfAttention(surprise, options_.focus);
  if (!step.focus.box.empty() && !expected_depth.empty())
    step.change = ClassifyChange(step.focus.region, depth, expected_depth, options_.change);
  // A region whose depth is the expected one within forget_after_frames of an added one still
  // holds that object: the appearance map takes each frame's depth into a view, so the frames
  // after an object appears soon predict it there (a static camera's at once).
  const ChangeKind kind = step.change.kind;
  const bool added =
      !step.focus.box.empty() && (kind == ChangeKind::kAdded ||
                                  (kind == ChangeKind::kUnknown && options_.learn_unknown_change));
  frames_since_added_ = added ? 0 : std::min(frames_since_added_ + 1, 1 << 30);
  const bool unchanged_object = kind == ChangeKind::kUnchanged &&
                                (frames_since_added_ <= options_.learner.forget_after_frames ||
                                 options_.learn_unchanged_change);
  step.learning = !step.focus.box.empty() && (added || unchanged_object);
  // Where something now stands that the map did not see, once per frame and only for an option
  // that uses it. Only an added region grows: grown in unchanged ones too, the focus took in
  // more and recognition found less (docs/objects.md).
  cv::Mat nearer;
  const bool added_uses_nearer = kind == ChangeKind::kAdded &&
                                 (options_.nearer_is_surprising || options_.grow_focus_over_nearer);
  const bool extract_uses_nearer =
      options_.learn_only_nearer_features && step.learning && !expected_depth.empty();
  if (added_uses_nearer || extract_uses_nearer)
    nearer = NearerMask(depth, expected_depth, options_.change);
  if (options_.grow_focus_over_nearer && kind == ChangeKind::kAdded)
    step.focus = GrowFocus(step.focus, nearer);
  SelectedFeatures features;
  if (step.learning) features = Extract(rgb, depth, nearer, step.focus.box, camera, step);
  // A frame that is not learnt from has no features: it counts towards forgetting.
  if (options_.nearer_is_surprising && kind == ChangeKind::kAdded)
    step.learner =
        learner_.Process(MarkSurprising(step.focus, nearer), features, camera, T_world_cam);
  else
    step.learner = learner_.Process(step.focus, features, camera, T_world_cam);
  return step;
}

SelectedFeatures ObjectAcquisition::Extract(const cv::Mat& rgb, const cv::Mat& depth,
                                            const cv::Mat& nearer, const cv::Rect& box,
                                            const core::PinholeCamera& camera,
                                            AcquisitionStep& step) {
  SelectedFeatures f;
  DetectAndComputeInBox(options_.extractor, *extractor_, rgb, box, options_.extraction_margin,
                        f.keypoints, f.descriptors);
  if (f.descriptors.type() != CV_32F && !f.keypoints.empty())
    f.descriptors.convertTo(f.descriptors, CV_32F);
  step.extracted = int(f.keypoints.size());
  if (options_.learn_only_nearer_features && !nearer.empty() && !f.keypoints.empty()) {
    std::vector<cv::KeyPoint> kept;
    cv::Mat kept_descriptors;
    for (std::size_t i = 0; i < f.keypoints.size(); ++i) {
      const std::optional<cv::Point> at = core::NearestPixel(f.keypoints[i].pt, nearer.size());
      if (!at || !nearer.at<uchar>(*at)) continue;
      kept.push_back(f.keypoints[i]);
      kept_descriptors.push_back(f.descriptors.row(int(i)));
    }
    step.not_nearer = step.extracted - int(kept.size());
    f.keypoints = std::move(kept);
    f.descriptors = kept_descriptors;
  }
  for (std::size_t i = 0; i < f.keypoints.size(); ++i) {
    const cv::Point2f& pt = f.keypoints[i].pt;
    const std::optional<cv::Point> at = core::NearestPixel(pt, depth.size());
    const float z = at ? depth.at<float>(*at) : 0.0f;
    if (z > 0.0f && std::isfinite(z)) {
      f.p_cam.emplace_back(camera.Unproject(pt.x, pt.y, z));
      ++step.reconstructed;
    } else {
      f.p_cam.emplace_back(std::nullopt);
    }
    f.max_descriptor_change.push_back(options_.relative_descriptor_change *
                                      cv::norm(f.descriptors.row(int(i))));
  }
  return f;
}

}  // namespace novelty::objects
