#include "sensors/localization/direct_odometry.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "sensors/localization/grey_image.h"

namespace novelty::sensors {
namespace {

cv::Mat Float(const cv::Mat& grey) {
  cv::Mat f;
  grey.convertTo(f, CV_32F);
  return f;
}

struct Keyframe {
  Eigen::Isometry3d world_from_camera;
  GradientPyramid pyramid;
  std::vector<Eigen::Vector3d> points;  // keyframe camera frame
  std::vector<cv::Point2f> px;          // where each was selected
  double median_depth = 1.0;
};

// One frame's images in the forms the steps need.
struct FrameImages {
  cv::Mat grey, other_grey;  // 8-bit, for ORB and KLT
  cv::Mat grey_f, other_grey_f;  // float, for the stereo depth of keyframes
  GradientPyramid pyramid;   // locally normalized, for the photometric alignment
  GradientPyramid other_pyramid;  // the same of the other image, when both are aligned
};

}  // namespace

class DirectOdometry::Impl {
 public:
  Impl(const DirectOdometryOptions& o, const Eigen::Isometry3d& p)
      : options(o), pose(p), relocalizer(o.relocalizer) {}
  DirectOdometryOptions options;
  Eigen::Isometry3d pose;
  std::vector<Keyframe> kept;  // keyframes taken (at most relocalizer.max_keyframes, at least
                               // one), to localize against; the last is the current one
  bool tracking = false;       // false before the first frame and after tracking loss
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();  // last frame-to-frame motion
  KeyframeRelocalizer relocalizer;

  // A keyframe at the current pose; also kept for re-localization.
  bool TakeKeyframe(const StereoPair& pair, const FrameImages& f, std::string* why) {
    const auto measured = EpipolarDepths(pair, f.grey_f, f.other_grey_f, options.depth);
    if (int(measured.size()) < options.min_points) {
      if (why) *why = "only " + std::to_string(measured.size()) + " pixels with stereo depth";
      return false;
    }
    Keyframe k;
    k.world_from_camera = pose;
    k.pyramid.image = f.pyramid.image;  // its gradients are never used: 0.4 MB, not 1.2 MB
    std::vector<float> depths;
    for (const EpipolarPoint& e : measured) {
      k.points.push_back(pair.reference_camera.Unproject(e.px.x, e.px.y, e.depth));
      k.px.push_back(e.px);
      depths.push_back(e.depth);
    }
    std::nth_element(depths.begin(), depths.begin() + depths.size() / 2, depths.end());
    k.median_depth = depths[depths.size() / 2];
    kept.push_back(std::move(k));
    if (kept.size() > std::max<size_t>(1, options.relocalizer.max_keyframes))
      kept.erase(kept.begin());
    tracking = true;
    relocalizer.Add(pair, f.grey, f.other_grey, pose);
    return true;
  }

  FrameImages Prepare(const StereoPair& pair) const {
    FrameImages f;
    f.grey = GreyImage(pair.reference);
    f.other_grey = GreyImage(pair.other);
    f.grey_f = Float(f.grey);
    f.other_grey_f = Float(f.other_grey);
    f.pyramid = GradientPyramid::Build(LocallyNormalized(f.grey_f, options.normalization),
                                       options.alignment.levels);
    if (options.align_both_images)
      f.other_pyramid = GradientPyramid::Build(
          LocallyNormalized(f.other_grey_f, options.normalization), options.alignment.levels);
    return f;
  }

  // The images a frame's pose is aligned to: the reference image, and the other if asked.
  std::vector<AlignmentView> Views(const StereoPair& pair, const FrameImages& f) const {
    std::vector<AlignmentView> v = {{&f.pyramid, pair.reference_camera}};
    if (options.align_both_images)
      v.push_back({&f.other_pyramid, pair.other_camera, pair.reference_from_other.inverse()});
    return v;
  }

  // Where ORB finds no match (under another lighting too few features match: I5 of the stereo
  // scenario): the frame aligned photometrically to each kept keyframe, starting from that
  // keyframe's own pose, and the best that aligns (lowest RMS within prior_max_rms) kept. A view
  // of a place the keyframes saw starts within the alignment's reach of one of them. One
  // alignment per kept keyframe: for frames of other sequences only, not after every tracking
  // loss.
  std::optional<Eigen::Isometry3d> AlignFromEachKeyframe(const StereoPair& pair,
                                                         const FrameImages& f) const {
    std::optional<Eigen::Isometry3d> best;
    double best_rms = options.prior_max_rms;
    for (const Keyframe& k : kept) {
      const AlignmentResult a = AlignPhotometric(k.points, k.px, k.pyramid, Views(pair, f),
                                                 Eigen::Isometry3d::Identity(), options.alignment);
      if (!Aligned(a, best_rms)) continue;
      best_rms = a.rms;
      best = k.world_from_camera * a.current_from_keyframe.inverse();
    }
    return best;
  }

  // The pose of a frame in this odometry's frame without tracking: `prior`, or else ORB + PnP
  // against the kept keyframes (and, when `exhaustive`, failing that AlignFromEachKeyframe),
  // gives a first pose, refined by photometric alignment to the kept keyframe nearest to it
  // (ORB alone is centimetres off).
  std::optional<Eigen::Isometry3d> Localize(const StereoPair& pair, const FrameImages& f,
                                            const std::optional<Eigen::Isometry3d>& prior,
                                            bool exhaustive, std::string* why) const {
    auto guess = prior ? prior : relocalizer.Relocalize(pair, f.grey);
    if (!guess && exhaustive) guess = AlignFromEachKeyframe(pair, f);
    if (!guess) {
      if (why) *why = exhaustive ? "no keyframe matches or aligns" : "no keyframe matches";
      return std::nullopt;
    }
    const Keyframe* nearest = nullptr;
    double nearest_cost = 0;
    for (const Keyframe& k : kept) {
      const Eigen::Isometry3d d = k.world_from_camera.inverse() * *guess;
      // Camera displacement plus the turn, both as shifts of the scene at the keyframe's depth.
      const double cost =
          d.translation().norm() + Eigen::AngleAxisd(d.linear()).angle() * k.median_depth;
      if (!nearest || cost < nearest_cost) nearest = &k, nearest_cost = cost;
    }
    if (!nearest) return guess;
    const AlignmentResult a = AlignPhotometric(nearest->points, nearest->px, nearest->pyramid,
                                               Views(pair, f),
                                               guess->inverse() * nearest->world_from_camera,
                                               options.alignment);
    const double max_rms = prior ? options.prior_max_rms : options.max_rms;
    if (!Aligned(a, max_rms)) {
      if (prior && why) {
        *why = "the frame does not align with the nearest keyframe (" + std::to_string(a.visible) +
               " points visible, min_points " + std::to_string(options.min_points) + "; rms " +
               std::to_string(a.rms) + ", prior_max_rms " + std::to_string(max_rms) +
               "; textured " + std::to_string(a.textured_fraction) + ", min_textured_fraction " +
               std::to_string(options.min_textured_fraction) + ")";
      }
      return prior ? std::nullopt : guess;
    }
    return nearest->world_from_camera * a.current_from_keyframe.inverse();
  }

  bool Aligned(const AlignmentResult& a, double max_rms) const {
    return a.visible >= options.min_points && a.rms <= max_rms &&
           a.textured_fraction >= options.min_textured_fraction;
  }

  bool NeedsKeyframe(const AlignmentResult& a) const {
    const Eigen::Isometry3d& t = a.current_from_keyframe;
    const double angle = Eigen::AngleAxisd(t.linear()).angle() * 180 / M_PI;
    const Keyframe& k = kept.back();
    return t.translation().norm() > options.keyframe_distance * k.median_depth ||
           angle > options.keyframe_angle_deg ||
           a.visible < options.min_visible_fraction * double(k.points.size());
  }
};

DirectOdometry::DirectOdometry(const DirectOdometryOptions& options,
                               const Eigen::Isometry3d& initial_pose)
    : impl_(std::make_unique<Impl>(options, initial_pose)) {}
DirectOdometry::~DirectOdometry() = default;

std::optional<DirectOdometryResult> DirectOdometry::Track(const StereoPair& pair,
                                                          std::string* why) {
  Impl& s = *impl_;
  auto fail = [&](const std::string& reason) -> std::optional<DirectOdometryResult> {
    if (why) *why = reason;
    return std::nullopt;
  };
  if (*StereoPairProblem(pair)) return fail(StereoPairProblem(pair));
  const FrameImages f = s.Prepare(pair);
  DirectOdometryResult result;
  std::string lost;
  if (s.tracking) {
    const Keyframe& keyframe = s.kept.back();
    // Constant-velocity prediction of T_cur_kf.
    const Eigen::Isometry3d kf_from_previous = keyframe.world_from_camera.inverse() * s.pose;
    const Eigen::Isometry3d predicted = (kf_from_previous * s.motion).inverse();
    const AlignmentResult a =
        AlignPhotometric(keyframe.points, keyframe.px, keyframe.pyramid,
                         s.Views(pair, f), predicted, s.options.alignment);
    if (s.Aligned(a, s.options.max_rms)) {
      const Eigen::Isometry3d world_from_camera =
          keyframe.world_from_camera * a.current_from_keyframe.inverse();
      s.motion = s.pose.inverse() * world_from_camera;
      s.pose = world_from_camera;
      result.world_from_camera = s.pose;
      result.points = a.visible;
      result.rms = a.rms;
      if (s.NeedsKeyframe(a)) result.new_keyframe = s.TakeKeyframe(pair, f, nullptr);
      return result;
    }
    lost = " (" + std::to_string(a.visible) + " points, photometric RMS " +
           std::to_string(int(a.rms)) + ")";
    s.tracking = false;
  }
  // The first frame starts at the given pose; after tracking loss the pose is re-localized.
  if (!s.kept.empty()) {
    const auto relocalized = s.Localize(pair, f, std::nullopt, false, nullptr);
    if (!relocalized) return fail("tracking lost" + lost + " and no keyframe matches");
    s.pose = *relocalized;
    result.relocalized = true;
  }
  if (!s.TakeKeyframe(pair, f, why)) return std::nullopt;
  s.motion = Eigen::Isometry3d::Identity();
  result.world_from_camera = s.pose;
  result.points = int(s.kept.back().points.size());
  result.new_keyframe = true;
  return result;
}

std::optional<Eigen::Isometry3d> DirectOdometry::Localize(
    const StereoPair& pair, std::string* why,
    const std::optional<Eigen::Isometry3d>& prior) const {
  if (*StereoPairProblem(pair)) {
    if (why) *why = StereoPairProblem(pair);
    return std::nullopt;
  }
  return impl_->Localize(pair, impl_->Prepare(pair), prior, true, why);
}

}  // namespace novelty::sensors
