#include "maps/appearance/prior_alignment.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "eval/attentional_selectivity.h"
#include "maps/appearance/appearance_map.h"
#include "sim/scenario/scenario_parser.h"
#include "sim/scenario/simulate_frames.h"
#include "tests/maps/appearance/table_clip.h"

namespace novelty::appearance {
namespace {

core::PinholeCamera Camera() {
  core::PinholeCamera c;
  c.width = 320, c.height = 240, c.fx = 440.0, c.fy = 440.0, c.cx = 159.5, c.cy = 119.5;
  return c;
}

// A textured luminance image of `size`: smoothed noise at two scales (in pixels of the 320×240
// frame, `scale` times finer here), 0…255.
cv::Mat Texture(int seed, cv::Size size, double scale) {
  cv::RNG rng{uint64_t(seed)};
  cv::Mat fine(size, CV_32FC1), coarse(size, CV_32FC1);
  rng.fill(fine, cv::RNG::UNIFORM, 0.0, 255.0);
  rng.fill(coarse, cv::RNG::UNIFORM, 0.0, 255.0);
  cv::GaussianBlur(fine, fine, cv::Size(), 1.5 * scale);
  cv::GaussianBlur(coarse, coarse, cv::Size(), 6.0 * scale);
  cv::Mat t = 2.0 * scale * (fine - 127.5) + 4.0 * scale * (coarse - 127.5) + 127.5;
  return cv::min(cv::max(t, 0.0), 255.0);
}

struct PriorAndFrame {
  cv::Mat prior, frame;
};

// What a camera sees of a textured plane at infinity, and what the camera rotated by R(ω) sees:
// frame(x) = prior(K·R·K⁻¹·x). Both are made independently of the module: the rotated rays are
// projected pixel by pixel into a texture four times finer, and each image is that texture's
// 4 × 4 pixel averages, as a sensor integrates light (no interpolation of the low-resolution
// image, whose errors would differ from the module's own).
PriorAndFrame Views(int seed, const core::PinholeCamera& c, const Eigen::Vector3d& omega) {
  const int k = 4;
  core::PinholeCamera fine = c;
  fine.width *= k, fine.height *= k, fine.fx *= k, fine.fy *= k;
  fine.cx = (c.cx + 0.5) * k - 0.5, fine.cy = (c.cy + 0.5) * k - 0.5;
  const cv::Mat texture = Texture(seed, {fine.width, fine.height}, k);
  const Eigen::Matrix3d R = RotationFromVector(omega);
  cv::Mat map_x(texture.size(), CV_32FC1), map_y(texture.size(), CV_32FC1);
  for (int y = 0; y < texture.rows; ++y)
    for (int x = 0; x < texture.cols; ++x) {
      const Eigen::Vector2d p = fine.Project(R * fine.RayCam(x, y));
      map_x.at<float>(y, x) = float(p.x());
      map_y.at<float>(y, x) = float(p.y());
    }
  cv::Mat rotated;
  cv::remap(texture, rotated, map_x, map_y, cv::INTER_CUBIC, cv::BORDER_REPLICATE);
  PriorAndFrame v;
  cv::resize(texture, v.prior, {c.width, c.height}, 0, 0, cv::INTER_AREA);
  cv::resize(rotated, v.frame, {c.width, c.height}, 0, 0, cv::INTER_AREA);
  return v;
}

// The largest distance (px) over the frame's corners between where R(estimate) and R(truth)
// move a pixel: what the estimate leaves of the motion.
double ResidualMotionPx(const core::PinholeCamera& c, const Eigen::Vector3d& estimate,
                        const Eigen::Vector3d& truth) {
  double worst = 0.0;
  for (double x : {0.0, c.width - 1.0})
    for (double y : {0.0, c.height - 1.0}) {
      const Eigen::Vector2d a = c.Project(RotationFromVector(estimate) * c.RayCam(x, y));
      const Eigen::Vector2d b = c.Project(RotationFromVector(truth) * c.RayCam(x, y));
      worst = std::max(worst, (a - b).norm());
    }
  return worst;
}

// A tracker-sized error (0.2°, about 1.5 px at 440 px focal length) in all three axes.
const Eigen::Vector3d kOmega(0.0021, -0.0028, 0.0017);

TEST(AlignRotationToPrior, RecoversAKnownRotation) {
  const core::PinholeCamera c = Camera();
  const PriorAndFrame v = Views(1, c, kOmega);
  const PriorAlignment a = AlignRotationToPrior(v.frame, v.prior, c);
  ASSERT_TRUE(a.aligned);
  EXPECT_GT(ResidualMotionPx(c, Eigen::Vector3d::Zero(), kOmega), 1.5);  // what there was
  // 0.02 px: at an edge of 50 levels per pixel that changes the colour by one level, the
  // sensor's noise; well below what surprise notices.
  EXPECT_LT(ResidualMotionPx(c, a.rotation, kOmega), 0.02);
}

TEST(AlignRotationToPrior, NoRotationGivesNone) {
  const core::PinholeCamera c = Camera();
  const cv::Mat prior = Views(2, c, Eigen::Vector3d::Zero()).prior;
  const PriorAlignment a = AlignRotationToPrior(prior, prior, c);
  ASSERT_TRUE(a.aligned);
  EXPECT_LT(a.rotation.norm(), 1e-6);
}

// What is new in the frame (a bright object over a tenth of it), a change of exposure and a
// quarter of the prior uncovered: Huber weights, the bias and the coverage mask keep the estimate.
TEST(AlignRotationToPrior, IgnoresANewObjectExposureAndUncoveredPixels) {
  const core::PinholeCamera c = Camera();
  const PriorAndFrame v = Views(3, c, kOmega);
  const cv::Mat& prior = v.prior;
  cv::Mat frame = v.frame + 12.0;
  frame(cv::Rect(200, 60, 90, 85)).setTo(250.0f);
  cv::Mat partial = prior.clone();
  partial(cv::Rect(0, 0, 80, 240)).setTo(std::numeric_limits<float>::quiet_NaN());
  const PriorAlignment a = AlignRotationToPrior(frame, partial, c);
  ASSERT_TRUE(a.aligned);
  // A tenth of a pixel: an order of magnitude below the tracker's error the alignment is for.
  EXPECT_LT(ResidualMotionPx(c, a.rotation, kOmega), 0.1);
  EXPECT_LT(a.pixels, 240 * 240);  // the uncovered quarter was not used
}

TEST(AlignRotationToPrior, RefusesWhatIsNotASmallError) {
  const core::PinholeCamera c = Camera();
  const PriorAndFrame v = Views(4, c, kOmega);
  const cv::Mat& prior = v.prior;
  // A flat prior has nothing to align on.
  EXPECT_FALSE(
      AlignRotationToPrior(prior, cv::Mat(240, 320, CV_32FC1, cv::Scalar(90.0)), c).aligned);
  // Everything uncovered.
  const cv::Mat none(240, 320, CV_32FC1, cv::Scalar(std::numeric_limits<float>::quiet_NaN()));
  const PriorAlignment n = AlignRotationToPrior(prior, none, c);
  EXPECT_FALSE(n.aligned);
  EXPECT_EQ(n.rotation, Eigen::Vector3d::Zero());
  // A flat frame, whatever the prior: nothing to align.
  const PriorAlignment flat =
      AlignRotationToPrior(cv::Mat(240, 320, CV_32FC1, cv::Scalar(30.0)), prior, c);
  EXPECT_FALSE(flat.aligned);
  EXPECT_EQ(flat.pixels, 0);
  // A rotation beyond max_rotation_rad.
  PriorAlignmentOptions o;
  o.max_rotation_rad = 0.001;
  EXPECT_FALSE(AlignRotationToPrior(v.frame, prior, c, o).aligned);
  // Steps left when the iterations run out: not converged, refused.
  o = {};
  o.max_iterations = 1;
  const PriorAlignment one = AlignRotationToPrior(v.frame, prior, c, o);
  EXPECT_FALSE(one.aligned);
  EXPECT_EQ(one.iterations, 1);
  EXPECT_EQ(one.rotation, Eigen::Vector3d::Zero());
  // Another scene altogether: no rotation explains it, and none may be applied.
  const PriorAlignment other = AlignRotationToPrior(Views(6, c, kOmega).frame, prior, c);
  EXPECT_FALSE(other.aligned) << "rotation " << other.rotation.transpose();
}

TEST(AlignRotationToPrior, RejectsBadPlanesAndOptions) {
  const core::PinholeCamera c = Camera();
  const cv::Mat prior = Views(5, c, Eigen::Vector3d::Zero()).prior;
  EXPECT_THROW(AlignRotationToPrior(prior(cv::Rect(0, 0, 100, 100)), prior, c),
               std::invalid_argument);
  cv::Mat bytes;
  prior.convertTo(bytes, CV_8U);
  EXPECT_THROW(AlignRotationToPrior(bytes, prior, c), std::invalid_argument);
  PriorAlignmentOptions o;
  o.max_iterations = 0;
  EXPECT_THROW(AlignRotationToPrior(prior, prior, c, o), std::invalid_argument);
  o = {};
  o.huber_levels = -1.0;
  EXPECT_THROW(AlignRotationToPrior(prior, prior, c, o), std::invalid_argument);
}

TEST(RotationFromVector, IsTheExponentialMap) {
  EXPECT_TRUE(RotationFromVector(Eigen::Vector3d::Zero()).isIdentity());
  const Eigen::Vector3d w(0.0, 0.0, M_PI / 2);
  // A quarter turn about +Z takes +X to +Y.
  EXPECT_TRUE(
      (RotationFromVector(w) * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY()));
}

struct AlignedRun {
  double quiet_surprise = 0.0;  // mean surprise (nats) over the second pass's frames
  double as_cup = 0.0;          // mean AS (dB) of the cup over the third pass
};

// The table clip (table_clip.h, exact RGB-D): the first pass at the true poses builds the map;
// from the second pass on the poses are off by a rotation that drifts as a smoothed tracker's
// does, 0.25–0.4° (about 0.6–1 px at this clip's 139 px focal length); a cup comes before the
// third pass.
AlignedRun PlayWithRotationError(bool align, bool perturb) {
  std::istringstream in(kClip);
  static const std::vector<sim::SimulatedFrame> clip =
      sim::SimulateFrames(sim::ParseScenario(in, "clip.scn"));
  const core::PinholeCamera cam = core::PinholeCamera::FromFov(160, 120, 60.0 * M_PI / 180);
  AppearanceMapOptions options;
  options.align_to_prior = align;
  AppearanceMap map(options);
  AlignedRun r;
  int quiet = 0, cup_frames = 0;
  for (const sim::SimulatedFrame& f : clip) {
    const double t = f.time;
    const Eigen::Vector3d error =
        t < 4.5 || !perturb
            ? Eigen::Vector3d::Zero()
            : Eigen::Vector3d(0.004 * std::sin(t), -0.004 * std::cos(0.7 * t), 0.003);
    const Eigen::Isometry3d given = f.T_world_cam * Eigen::Isometry3d(RotationFromVector(error));
    const AppearanceProducts p = map.Insert(f.rgb, f.depth, cam, given);
    if (t > 5.0 && t < 8.5) {  // the second pass: nothing has changed
      cv::Mat s = p.surprise.clone();
      s.setTo(0.0f, s != s);
      r.quiet_surprise += cv::mean(s, p.valid)[0];
      ++quiet;
    }
    const cv::Mat cup = f.novelty == 255;
    if (t > 9.5 && cv::countNonZero(cup) > 50) {
      r.as_cup += eval::AttentionalSelectivity(p.surprise, cup).as_db;
      ++cup_frames;
    }
  }
  r.quiet_surprise /= std::max(1, quiet);
  r.as_cup /= std::max(1, cup_frames);
  return r;
}

// A rotation error of a smoothed tracker's size: without the alignment it shows as surprise in
// the unchanged scene and takes selectivity from the cup; aligned, the map is as calm (within
// 10 %) and the cup as selective (within 0.5 dB) as at the true poses.
TEST(AppearanceMapAlignedToPrior, TakesOutARotationError) {
  const AlignedRun aligned = PlayWithRotationError(true, true);
  const AlignedRun plain = PlayWithRotationError(false, true);
  const AlignedRun exact = PlayWithRotationError(false, false);
  std::printf(
      "mean surprise %.3f aligned, %.3f without, %.3f at the true poses; cup AS %.2f, "
      "%.2f, %.2f dB\n",
      aligned.quiet_surprise, plain.quiet_surprise, exact.quiet_surprise, aligned.as_cup,
      plain.as_cup, exact.as_cup);
  EXPECT_GT(plain.quiet_surprise, 1.1 * exact.quiet_surprise) << "the error must show";
  EXPECT_LT(plain.as_cup, exact.as_cup - 0.5) << "the error must show";
  EXPECT_LT(aligned.quiet_surprise, 1.1 * exact.quiet_surprise);
  EXPECT_GT(aligned.as_cup, exact.as_cup - 0.5);
}

// At the true poses the alignment changes nothing of note.
TEST(AppearanceMapAlignedToPrior, LeavesTruePosesAsGoodAsTheyAre) {
  const AlignedRun aligned = PlayWithRotationError(true, false);
  const AlignedRun exact = PlayWithRotationError(false, false);
  EXPECT_LT(aligned.quiet_surprise, 1.1 * exact.quiet_surprise);
  EXPECT_GT(aligned.as_cup, exact.as_cup - 0.5);
}

}  // namespace
}  // namespace novelty::appearance
