#include "maps/objects/object_learner.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "maps/objects/object_recognition.h"
#include "maps/objects/ratio_matches.h"

namespace novelty::objects {

ObjectLearner::ObjectLearner(const ObjectLearnerOptions& options) : options_(options) {
  if (!(options.static_distance_px > 0.0) ||
      !(options.match_ratio > 0.0 && options.match_ratio <= 1.0) ||
      !(options.min_surprising_share >= 0.0 && options.min_surprising_share <= 1.0) ||
      !(options.window_per_scale > 0.0) || !(options.size_per_scale > 0.0) ||
      options.forget_after_frames < 1 ||
      (options.window_angle_sign != 1 && options.window_angle_sign != -1))
    throw std::invalid_argument(
        "ObjectLearnerOptions: static_distance_px > 0, match_ratio in "
        "(0, 1], min_surprising_share in [0, 1], window_per_scale > 0, "
        "size_per_scale > 0, forget_after_frames >= 1, window_angle_sign ±1");
}

bool ObjectLearner::MatchesActiveFeatures(const cv::Mat& descriptors) const {
  cv::Mat active_descriptors;
  for (const ActiveFeature& g : active_) active_descriptors.push_back(g.descriptor);
  return !RatioMatches(active_descriptors, descriptors, options_.match_ratio).empty();
}

LearnerStep ObjectLearner::Process(const FocusOfAttention& focus, const SelectedFeatures& f,
                                   const core::PinholeCamera& camera,
                                   const Eigen::Isometry3d& T_world_cam) {
  const std::size_t n = f.keypoints.size();
  if (int(n) != f.descriptors.rows || f.p_cam.size() != n || f.max_descriptor_change.size() != n)
    throw std::invalid_argument("ObjectLearner::Process: " + std::to_string(n) + " keypoints, " +
                                std::to_string(f.descriptors.rows) + " descriptors, " +
                                std::to_string(f.p_cam.size()) + " positions, " +
                                std::to_string(f.max_descriptor_change.size()) + " bounds");
  LearnerStep step;
  step.selected = int(n);
  if (n == 0) {  // the object may have gone
    if (++frames_without_features_ >= options_.forget_after_frames) {
      active_.clear();
      learning_object_ = -1;
    }
  } else {
    frames_without_features_ = 0;
  }
  if (n == 0) {
    step.matches_per_object.assign(std::size_t(database_.objects()), 0);
    step.active = int(active_.size());
    return step;
  }

  // 1. Static features (eq. 5.1, 5.2), and which of them lie mostly on surprise (eq. 5.5).
  const std::vector<int> statics = StaticFeatures(f.keypoints, f.descriptors, active_, camera,
                                                  T_world_cam, options_.static_distance_px);
  step.static_features = int(statics.size());
  std::vector<int> on_surprise;
  for (int i : statics) {
    const cv::KeyPoint& k = f.keypoints[std::size_t(i)];
    const float window = float(options_.window_per_scale * k.size / options_.size_per_scale);
    const float angle = float(options_.window_angle_sign * k.angle * M_PI / 180.0);
    if (SurprisingShare(focus, k.pt, window, angle) > options_.min_surprising_share)
      on_surprise.push_back(i);
  }

  // 2. Recognition: the database first (eq. 5.4), then the active features.
  const FeatureDatabase::Recognition r = database_.Recognize(
      f.descriptors, options_.match_ratio, options_.distinct_second_match ? &f.keypoints : nullptr);
  step.matches_per_object = r.matches_per_object;
  std::vector<bool> in_database(n, false);
  for (const RatioMatch& m : r.matches) in_database[std::size_t(m.candidate)] = true;
  if (r.object >= 0 && options_.verify_pose) {
    step.verification = VerifyObjectMatches(database_, r.matches, f.keypoints, r.object, camera,
                                            options_.verification);
    step.verification_tried = true;
  }
  if (r.object >= 0 && (!options_.verify_pose || step.verification.verified)) {
    step.recognised = LearnerStep::Recognised::kByDatabase;
    step.object = r.object;
  } else {
    const bool by_active = (options_.static_features_recognise && !statics.empty()) ||
                           MatchesActiveFeatures(f.descriptors);
    if (by_active && learning_object_ >= 0) {
      step.recognised = LearnerStep::Recognised::kByActiveFeatures;
      step.object = learning_object_;
    } else if (!on_surprise.empty()) {  // an unknown object (eq. 5.5)
      step.recognised = LearnerStep::Recognised::kNewObject;
      step.object = database_.AddObject();
    } else if (by_active) {
      step.recognised = LearnerStep::Recognised::kByActiveFeatures;  // not yet a class to learn
    }
  }

  // 3. Learning (eq. 5.6, 5.7): static features on surprise that the database does not hold.
  if (step.object >= 0) {
    cv::Mat learnt;
    std::vector<Eigen::Vector3d> positions;
    std::vector<LearntKeypoint> keypoints;
    for (int i : on_surprise) {
      if (in_database[std::size_t(i)]) continue;
      learnt.push_back(f.descriptors.row(i));
      const std::optional<Eigen::Vector3d>& p = f.p_cam[std::size_t(i)];
      positions.push_back(p ? Eigen::Vector3d(T_world_cam * *p)
                            : Eigen::Vector3d::Constant(std::nan("")));
      const cv::KeyPoint& k = f.keypoints[std::size_t(i)];
      keypoints.push_back(ToLearntKeypoint(k, MetricSize(k, p ? p->z() : std::nan(""), camera)));
    }
    if (!learnt.empty()) database_.AddFeatures(learnt, step.object, positions, keypoints);
    step.learnt = learnt.rows;
    learning_object_ = step.object;
  }

  // 4. New active features: reconstructed, neither static nor in the database, and where no
  // active feature already reprojects within δ: a place is held once, so that the active
  // features grow with what is seen, not with the frames a lasting surprise is seen for.
  std::vector<bool> is_static(n, false);
  for (int i : statics) is_static[std::size_t(i)] = true;
  // (Only the pixels are read: the pointers into active_ do not outlive the push_backs below.)
  const std::vector<ProjectedActiveFeature> held =
      ProjectActiveFeatures(active_, camera, T_world_cam);
  const auto is_held = [&](const cv::Point2f& pt) {
    for (const ProjectedActiveFeature& g : held)
      if ((g.pixel - Eigen::Vector2d(pt.x, pt.y)).norm() < options_.static_distance_px) return true;
    return false;
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (is_static[i] || in_database[i] || !f.p_cam[i] || is_held(f.keypoints[i].pt)) continue;
    active_.push_back(
        {T_world_cam * *f.p_cam[i], f.descriptors.row(int(i)).clone(), f.max_descriptor_change[i]});
    ++step.new_active;
  }
  step.active = int(active_.size());
  return step;
}

}  // namespace novelty::objects
