#include "sensors/localization/visual_odometry.h"

#include <algorithm>
#include <map>

#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

#include "sensors/localization/grey_image.h"
#include "sensors/localization/opencv_pose.h"
#include "sensors/tracker/rigid_fit.h"

namespace novelty::sensors {
namespace {

struct Feature {
  cv::Point2f px;         // in the latest reference image
  Eigen::Vector3d world;  // triangulated when new, then kept
  int anchor_frame;       // the frame it was detected in
  cv::Point2f anchor_px;  // and where
  int observations = 1;   // triangulations averaged into `world`; 1 = not yet confirmed
};

cv::Point3f ToCv(const Eigen::Vector3d& p) {
  return {float(p.x()), float(p.y()), float(p.z())};
}

double Tukey(double r, double c) {
  if (r >= c) return 0.0;
  const double u = r / c;
  return (1 - u * u) * (1 - u * u);
}

}  // namespace

class VisualOdometry::Impl {
 public:
  Impl(const VisualOdometryOptions& o, const Eigen::Isometry3d& initial)
      : options(o), pose(initial), relocalizer(o.relocalizer) {}

  VisualOdometryOptions options;
  Eigen::Isometry3d pose;
  bool started = false;
  int frame = 0;
  cv::Mat previous_grey;
  std::vector<Feature> features;
  std::map<int, cv::Mat> anchors;  // grey images features were detected in, while in use
  KeyframeRelocalizer relocalizer;

  // Focal length × baseline: converts a depth error at depth Z into disparity pixels (·/Z²).
  static double FocalBaseline(const StereoPair& p) {
    return std::abs(p.reference_camera.fx) * p.reference_from_other.translation().norm();
  }

  void TrackFeatures(const cv::Mat& grey) {
    if (features.empty()) return;
    std::vector<cv::Point2f> from, to, back;
    for (const Feature& f : features) from.push_back(f.px);
    std::vector<unsigned char> status, status_back;
    std::vector<float> err;
    const cv::Size win(options.stereo.klt_window, options.stereo.klt_window);
    cv::calcOpticalFlowPyrLK(previous_grey, grey, from, to, status, err, win, 3);
    cv::calcOpticalFlowPyrLK(grey, previous_grey, to, back, status_back, err, win, 3);
    std::vector<Feature> kept;
    for (size_t i = 0; i < features.size(); ++i) {
      if (!status[i] || !status_back[i] || cv::norm(back[i] - from[i]) > options.max_track_error)
        continue;
      if (to[i].x < 0 || to[i].y < 0 || to[i].x > grey.cols - 1 || to[i].y > grey.rows - 1)
        continue;
      Feature f = features[i];
      f.px = to[i];
      kept.push_back(f);
    }
    features.swap(kept);
    RefineAgainstAnchors(grey);
  }

  // Frame-to-frame KLT drifts by a fraction of a pixel per frame (its template is the last
  // image). Re-aligning each feature with its appearance where it was detected removes the
  // drift; a feature whose appearance no longer matches is dropped.
  void RefineAgainstAnchors(const cv::Mat& grey) {
    std::map<int, std::vector<size_t>> by_anchor;
    for (size_t i = 0; i < features.size(); ++i) by_anchor[features[i].anchor_frame].push_back(i);
    std::vector<bool> keep(features.size(), true);
    const cv::Size win(options.stereo.klt_window, options.stereo.klt_window);
    for (const auto& [frame_id, members] : by_anchor) {
      std::vector<cv::Point2f> from, to;
      for (size_t i : members) from.push_back(features[i].anchor_px), to.push_back(features[i].px);
      std::vector<unsigned char> status;
      std::vector<float> err;
      cv::calcOpticalFlowPyrLK(
          anchors.at(frame_id), grey, from, to, status, err, win, 1,
          cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 30, 0.01),
          cv::OPTFLOW_USE_INITIAL_FLOW);
      for (size_t j = 0; j < members.size(); ++j) {
        Feature& f = features[members[j]];
        if (!status[j] || cv::norm(to[j] - f.px) > options.max_anchor_shift) {
          keep[members[j]] = false;
          continue;
        }
        f.px = to[j];
      }
    }
    std::vector<Feature> kept;
    for (size_t i = 0; i < features.size(); ++i)
      if (keep[i]) kept.push_back(features[i]);
    features.swap(kept);
    // Forget anchor images no feature refers to any more.
    for (auto it = anchors.begin(); it != anchors.end();) {
      const bool used = std::any_of(features.begin(), features.end(),
                                    [&](const Feature& f) { return f.anchor_frame == it->first; });
      it = used ? std::next(it) : anchors.erase(it);
    }
  }

  // Inliers and a first pose by PnP + RANSAC on the reprojections (robust against the heavy tail
  // of "corners" at occlusion boundaries that no 3D point explains); nullopt if it fails.
  std::optional<Eigen::Isometry3d> RansacPose(const std::vector<Eigen::Vector3d>& world,
                                              const std::vector<cv::Point2f>& image,
                                              const core::PinholeCamera& c,
                                              std::vector<bool>& inlier) {
    std::vector<cv::Point3f> object;
    for (const auto& w : world) object.push_back(ToCv(w));
    const cv::Mat k = CameraMatrix(c);
    cv::Mat rvec, tvec;
    ToRvecTvec(pose, rvec, tvec);  // the previous pose as the starting guess
    std::vector<int> inliers;
    if (!cv::solvePnPRansac(object, image, k, cv::noArray(), rvec, tvec, true, 100,
                            float(options.ransac_reprojection_px), 0.999, inliers))
      return std::nullopt;
    inlier.assign(world.size(), false);
    for (int i : inliers) inlier[i] = true;
    if (options.pose_from_reprojection) {  // refine on the inliers by Levenberg–Marquardt
      std::vector<cv::Point3f> o2;
      std::vector<cv::Point2f> i2;
      for (int i : inliers) o2.push_back(object[i]), i2.push_back(image[i]);
      cv::solvePnPRefineLM(o2, i2, k, cv::noArray(), rvec, tvec);
    }
    return WorldFromRvecTvec(rvec, tvec);
  }

  // eq. 3.1–3.4, iterated from `start`: Tukey weights from the residuals of the previous fit,
  // zero for RANSAC outliers.
  std::optional<Eigen::Isometry3d> FitPose(const std::vector<Eigen::Vector3d>& world,
                                           const std::vector<Eigen::Vector3d>& camera,
                                           const std::vector<bool>& inlier, double fb,
                                           const Eigen::Isometry3d& start,
                                           std::vector<double>& weights) {
    weights.assign(world.size(), 1.0);
    Eigen::Isometry3d cam_from_world = start.inverse();
    for (int it = 0; it < options.fit_iterations; ++it) {
      for (size_t i = 0; i < world.size(); ++i) {
        const double z = std::max(0.1, camera[i].z());
        const double residual_px = (camera[i] - cam_from_world * world[i]).norm() * fb / (z * z);
        weights[i] = inlier[i] ? Tukey(residual_px, options.outlier_threshold_px) : 0.0;
      }
      std::string why;
      const auto fit = FitRigid(world, camera, weights, &why);
      if (!fit) return std::nullopt;
      cam_from_world = fit->transform;
    }
    return cam_from_world.inverse();
  }

  void DetectNew(const StereoPair& pair, const cv::Mat& grey, const cv::Mat& other_grey) {
    const int cw = grey.cols / options.grid_columns, ch = grey.rows / options.grid_rows;
    std::vector<int> count(options.grid_columns * options.grid_rows, 0);
    cv::Mat mask(grey.size(), CV_8U, cv::Scalar(255));
    for (const Feature& f : features) {
      const int cx = std::min(options.grid_columns - 1, int(f.px.x) / cw);
      const int cy = std::min(options.grid_rows - 1, int(f.px.y) / ch);
      ++count[cy * options.grid_columns + cx];
      cv::circle(mask, f.px, 6, cv::Scalar(0), -1);
    }
    std::vector<cv::Point2f> candidates;
    for (int cy = 0; cy < options.grid_rows; ++cy)
      for (int cx = 0; cx < options.grid_columns; ++cx) {
        const int want = options.features_per_cell - count[cy * options.grid_columns + cx];
        if (want <= 0) continue;
        const cv::Rect cell(cx * cw, cy * ch, cw, ch);
        std::vector<cv::Point2f> corners;
        cv::goodFeaturesToTrack(grey(cell), corners, want, 0.01, 6, mask(cell));
        for (const cv::Point2f& c : corners) candidates.push_back(c + cv::Point2f(cell.tl()));
      }
    if (candidates.empty()) return;
    const bool bootstrap = std::none_of(features.begin(), features.end(),
                                        [](const Feature& f) { return f.observations > 1; });
    cv::cornerSubPix(grey, candidates, cv::Size(4, 4), cv::Size(-1, -1),
                     cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 20, 0.01));
    const auto points = TriangulateFeatures(pair, grey, other_grey, candidates, options.stereo);
    bool any = false;
    for (size_t i = 0; i < candidates.size(); ++i)
      if (points[i]) {
        // With no confirmed feature left (first frame, after re-localization) the new ones are
        // confirmed at once: there is nothing to check them against.
        features.push_back(
            {candidates[i], pose * *points[i], frame, candidates[i], bootstrap ? 2 : 1});
        any = true;
      }
    if (any) anchors[frame] = grey;
  }
};

VisualOdometry::VisualOdometry(const VisualOdometryOptions& options,
                               const Eigen::Isometry3d& initial_pose)
    : impl_(std::make_unique<Impl>(options, initial_pose)) {}

VisualOdometry::~VisualOdometry() = default;

std::optional<VisualOdometryResult> VisualOdometry::Track(const StereoPair& pair,
                                                          std::string* why) {
  Impl& s = *impl_;
  auto fail = [&](const std::string& reason) -> std::optional<VisualOdometryResult> {
    if (why) *why = reason;
    return std::nullopt;
  };
  if (*StereoPairProblem(pair)) return fail(StereoPairProblem(pair));
  const cv::Mat grey = GreyImage(pair.reference), other_grey = GreyImage(pair.other);
  const double fb = Impl::FocalBaseline(pair);
  VisualOdometryResult result;
  ++s.frame;
  if (!s.started) {
    s.DetectNew(pair, grey, other_grey);
    if (int(s.features.size()) < s.options.min_inliers)
      return fail("only " + std::to_string(s.features.size()) + " features in the first frame");
    s.started = true;
  } else {
    s.TrackFeatures(grey);
    result.tracked = int(s.features.size());
    std::vector<cv::Point2f> px;
    for (const Feature& f : s.features) px.push_back(f.px);
    const auto camera_points = TriangulateFeatures(pair, grey, other_grey, px, s.options.stereo);
    std::vector<Eigen::Vector3d> world, camera;
    std::vector<cv::Point2f> image;
    std::vector<size_t> index;
    for (size_t i = 0; i < s.features.size(); ++i)
      if (camera_points[i] && s.features[i].observations > 1) {
        world.push_back(s.features[i].world);
        camera.push_back(*camera_points[i]);
        image.push_back(s.features[i].px);
        index.push_back(i);
      }
    std::vector<double> weights;
    std::vector<bool> inlier;
    std::optional<Eigen::Isometry3d> pose;
    if (int(world.size()) >= s.options.min_inliers)
      pose = s.RansacPose(world, image, pair.reference_camera, inlier);
    if (pose && s.options.pose_from_reprojection)
      for (size_t i = 0; i < world.size(); ++i) weights.push_back(inlier[i] ? 1.0 : 0.0);
    else if (pose)
      pose = s.FitPose(world, camera, inlier, fb, *pose, weights);
    const int inliers =
        int(std::count_if(weights.begin(), weights.end(), [](double w) { return w > 0; }));
    if (!pose || inliers < s.options.min_inliers) {
      const auto relocalized = s.relocalizer.Relocalize(pair, grey);
      if (!relocalized) {
        s.previous_grey = grey;
        s.features.clear();
        return fail("tracking lost (" + std::to_string(inliers) +
                    " inliers) and no keyframe matches");
      }
      s.pose = *relocalized;
      s.features.clear();
      result.relocalized = true;
    } else {
      s.pose = *pose;
      result.inliers = inliers;
      // Keep the features that fitted (outliers: moving objects, mismatches), and confirm new
      // ones whose second triangulation agrees with the first: a "corner" where two surfaces
      // meet at an occlusion boundary moves with the viewpoint and is dropped here. Each
      // triangulation is averaged into the feature's world position (3.1.1: points refined).
      std::vector<bool> fitted(s.features.size(), false);
      for (size_t j = 0; j < index.size(); ++j) fitted[index[j]] = weights[j] > 0;
      std::vector<Feature> kept;
      for (size_t i = 0; i < s.features.size(); ++i) {
        Feature f = s.features[i];
        if (f.observations > 1 && !fitted[i]) continue;
        if (!camera_points[i]) {
          if (f.observations > 1) kept.push_back(f);
          continue;
        }
        const Eigen::Vector3d now = s.pose * *camera_points[i];
        const double z = std::max(0.1, camera_points[i]->z());
        const double residual_px = (now - f.world).norm() * fb / (z * z);
        if (f.observations == 1 && residual_px > s.options.outlier_threshold_px) continue;
        f.world = (f.world * f.observations + now) / (f.observations + 1);
        ++f.observations;
        kept.push_back(f);
      }
      s.features.swap(kept);
    }
    if (int(s.features.size()) < s.options.min_features) s.DetectNew(pair, grey, other_grey);
  }
  if (s.options.keyframe_every > 0 && (s.frame - 1) % s.options.keyframe_every == 0)
    s.relocalizer.Add(pair, grey, other_grey, s.pose);
  s.previous_grey = grey;
  result.world_from_camera = s.pose;
  if (result.inliers == 0) result.inliers = int(s.features.size());
  return result;
}

}  // namespace novelty::sensors
