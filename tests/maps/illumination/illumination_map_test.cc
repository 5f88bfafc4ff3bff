#include "maps/illumination/illumination_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace novelty::illumination {
namespace {

// A textured wall 2 m in front of a camera that slides sideways, seen under several lightings:
// each lighting scales the light and throws a disc-shaped shadow (×0.4) at a place of its own,
// so that at every pixel the shadow's edges are a minority and the median of the gradients is
// the reflectance's (6.1.2). Everything is analytic in wall coordinates, so any viewpoint's true
// log reflectance is known.
constexpr double kWall = 2.0;

core::PinholeCamera Camera() {
  core::PinholeCamera c;
  c.width = 160;
  c.height = 120;
  c.fx = c.fy = 150.0;
  c.cx = 79.5;
  c.cy = 59.5;
  return c;
}

struct Lighting {
  double scale = 1.0;
  cv::Point2d shadow{100, 100};  // wall coordinates of the shadow's centre (far away: none)
  double shadow_radius = 0.15;
};

struct NewObject {
  cv::Rect2d box;  // wall coordinates
  cv::Vec3d factor{1, 1, 1};
};

cv::Vec3d Reflectance(double X, double Y) {
  return {60 + 35 * std::sin(9 * X) * std::cos(6 * Y), 70 + 30 * std::cos(7 * X + 1),
          55 + 30 * std::sin(8 * Y + 2 * X)};
}

core::Frame Render(double x, const Lighting& light, int index, const NewObject* object = nullptr,
                   cv::Mat* truth = nullptr, cv::Mat* log_reflectance = nullptr,
                   cv::Mat* shadow = nullptr) {
  core::Frame f;
  f.index = index;
  f.camera = Camera();
  f.T_world_cam = Eigen::Isometry3d(Eigen::Translation3d(x, 0, 0));
  f.rgb.create(f.camera.height, f.camera.width, CV_8UC3);
  f.depth = cv::Mat(f.rgb.size(), CV_32F, cv::Scalar(kWall));
  if (truth) *truth = cv::Mat::zeros(f.rgb.size(), CV_8U);
  if (log_reflectance) log_reflectance->create(f.rgb.size(), CV_32FC3);
  if (shadow) *shadow = cv::Mat::zeros(f.rgb.size(), CV_8U);
  cv::RNG rng(uint64_t(index) * 7919u + 1u);
  for (int v = 0; v < f.rgb.rows; ++v)
    for (int u = 0; u < f.rgb.cols; ++u) {
      const double X = x + (u - f.camera.cx) / f.camera.fx * kWall;
      const double Y = (v - f.camera.cy) / f.camera.fy * kWall;
      cv::Vec3d r = Reflectance(X, Y);
      if (log_reflectance)
        for (int c = 0; c < 3; ++c) log_reflectance->at<cv::Vec3f>(v, u)[c] = float(std::log(r[c]));
      if (object && object->box.contains({X, Y})) {
        for (int c = 0; c < 3; ++c) r[c] *= object->factor[c];
        if (truth) truth->at<uchar>(v, u) = 255;
      }
      double l = light.scale;
      if (std::hypot(X - light.shadow.x, Y - light.shadow.y) < light.shadow_radius) {
        l *= 0.4;
        if (shadow) shadow->at<uchar>(v, u) = 255;
      }
      for (int c = 0; c < 3; ++c)
        f.rgb.at<cv::Vec3b>(v, u)[c] = cv::saturate_cast<uchar>(r[c] * l + rng.uniform(-1.0, 1.0));
    }
  return f;
}

const std::vector<Lighting> kLightings = {{0.8, {0.10, 0.30}},
                                          {1.2, {0.35, -0.25}},
                                          {1.0, {-0.20, -0.05}},
                                          {0.9, {0.55, 0.20}},
                                          {1.3, {0.00, 0.40}}};

IlluminationMap Learnt(const IlluminationMapOptions& options = {}) {
  IlluminationMap map(options);
  int index = 0;
  for (const Lighting& light : kLightings) {
    map.BeginLighting();
    for (int k = 0; k <= 15; ++k) map.AddTrainingFrame(Render(0.02 * k, light, ++index));
  }
  map.Build();
  return map;
}

double Rms(const cv::Mat& a, const cv::Mat& mask) {
  cv::Mat d;
  cv::multiply(a, a, d);
  return std::sqrt(cv::mean(d, mask)[0]);
}

TEST(IlluminationMap, ViewpointsAlongTheFirstLightingsPath) {
  const IlluminationMap map = Learnt();
  EXPECT_EQ(map.lightings(), 5);
  // 0 … 0.30 m in 2 cm steps, a viewpoint every 5 cm or more: 0, 0.06, 0.12, 0.18, 0.24, 0.30.
  EXPECT_EQ(map.size(), 6);
  EXPECT_EQ(map.dropped_viewpoints(), 0);
  for (int i = 0; i < map.size(); ++i) {
    EXPECT_GT(map.model(i).coverage, 0.95) << "viewpoint " << i;
    EXPECT_EQ(map.view(i).planes.at("shapes").channels(), 5);
  }
}

TEST(IlluminationMap, InterpolatedInvariantImageIsTheLogReflectance) {
  // Between viewpoints, the interpolated r̂ equals log R up to a constant per channel (6.1.2:
  // r̂ is defined up to one), so after removing each channel's mean the error is the noise's.
  const IlluminationMap map = Learnt();
  cv::Mat log_r;
  const core::Frame frame =
      Render(0.16, {1.05, {100, 100}}, 1000, nullptr, nullptr, &log_r, nullptr);
  const IlluminationMapResult r = map.Detect(frame);
  EXPECT_GT(r.coverage, 0.9);
  ASSERT_GE(r.viewpoints.size(), 1u);
  std::vector<cv::Mat> est, tru;
  cv::split(r.viewpoint.log_invariant, est);
  cv::split(log_r, tru);
  for (int c = 0; c < 3; ++c) {
    cv::Mat d = est[c] - tru[c];
    d -= cv::mean(d, r.viewpoint.covered)[0];
    // Noise ±1 on values 30…130 is at most 0.03 in log; the reflectance varies by ±0.5.
    EXPECT_LT(Rms(d, r.viewpoint.covered), 0.03) << "channel " << c;
  }
}

TEST(IlluminationMap, AtTheEdgeOfAViewpointsCoverageTheInvariantIsNotDimmed) {
  // Two lightings, the second seen only from the first 10 cm of the path: the viewpoints farther
  // along have an invariant value only where its virtual images reach, and a frame there sees
  // the border. Along it the blend mixes samples with and without a value; r̂ must still be the
  // average over the samples that have one (r̂ is stored as 0 where there is none).
  IlluminationMap map;
  map.BeginLighting();
  for (int k = 0; k <= 15; ++k) map.AddTrainingFrame(Render(0.02 * k, kLightings[0], k + 1));
  map.BeginLighting();
  for (int k = 0; k <= 5; ++k) map.AddTrainingFrame(Render(0.02 * k, kLightings[1], k + 20));
  map.Build();
  cv::Mat log_r;
  const core::Frame frame =
      Render(0.29, {1.05, {100, 100}}, 1001, nullptr, nullptr, &log_r, nullptr);
  const IlluminationMapResult r = map.Detect(frame);
  ASSERT_GT(r.coverage, 0.3);
  ASSERT_LT(r.coverage, 0.95);
  std::vector<cv::Mat> est, tru;
  cv::split(r.viewpoint.log_invariant, est);
  cv::split(log_r, tru);
  for (int c = 0; c < 3; ++c) {
    cv::Mat d = est[c] - tru[c];
    d -= cv::mean(d, r.viewpoint.covered)[0];
    double worst = 0.0;
    cv::minMaxLoc(cv::abs(d), nullptr, &worst, nullptr, nullptr, r.viewpoint.covered);
    // Log values are about 4: a border pixel at 60 % coverage would be 1.6 off. Two lightings
    // leave the shadows' edges in (the median of two is their mean): 0.5 at most.
    EXPECT_LT(worst, 0.5) << "channel " << c;
  }
}

TEST(IlluminationMap, AFailedBuildLeavesTheMapToGoOn) {
  IlluminationMap map;
  map.BeginLighting();
  for (int k = 0; k <= 15; ++k) map.AddTrainingFrame(Render(0.02 * k, kLightings[0], k + 1));
  EXPECT_THROW(map.Build(), std::invalid_argument);  // one lighting
  EXPECT_FALSE(map.built());
  map.BeginLighting();
  for (int k = 0; k <= 15; ++k) map.AddTrainingFrame(Render(0.02 * k, kLightings[1], k + 20));
  map.Build();
  EXPECT_EQ(map.lightings(), 2);
  EXPECT_EQ(map.size(), 6);
  EXPECT_EQ(map.view(0).planes.at("shapes").channels(), 2);
  // A loaded viewpoint cannot join a map that is acquiring.
  IlluminationMap acquiring;
  acquiring.AddTrainingFrame(Render(0, kLightings[0], 1));
  EXPECT_THROW(acquiring.AddViewpoint(map.view(0), map.model(0), 2), std::logic_error);
  // Nor one of another lighting count into a map.
  IlluminationMap loaded;
  loaded.AddViewpoint(map.view(0), map.model(0), 2);
  EXPECT_THROW(loaded.AddViewpoint(map.view(1), map.model(1), 3), std::invalid_argument);
}

TEST(IlluminationMap, ALoadedMissingTextureModelIsChecked) {
  IlluminationMapOptions options;
  options.model.missing_texture = true;
  const IlluminationMap map = Learnt(options);
  ASSERT_FALSE(map.model(0).model.texture.empty());
  ASSERT_EQ(map.view(0).planes.count("texture"), 1u);
  const auto refused = [&](views::ReferenceView view, IlluminationViewpointModel model) {
    IlluminationMap loaded;
    loaded.AddViewpoint(map.view(1), map.model(1), map.lightings());
    EXPECT_THROW(loaded.AddViewpoint(std::move(view), std::move(model), map.lightings()),
                 std::invalid_argument);
  };
  views::ReferenceView zero = map.view(0);
  zero.planes["texture"] = cv::Mat::zeros(zero.planes["texture"].size(), CV_32F);
  refused(zero, map.model(0));  // a scale of 0 where covered: every frame would saturate i_T
  views::ReferenceView nan = map.view(0);
  nan.planes["texture"] = cv::Mat(nan.planes["texture"].size(), CV_32F, cv::Scalar(NAN));
  refused(nan, map.model(0));
  IlluminationViewpointModel huge = map.model(0);
  huge.model.texture_block = 1000001;  // seconds a frame
  refused(map.view(0), huge);
  IlluminationViewpointModel shorter = map.model(0);
  shorter.model.texture.values.resize(8);  // MeanTail could not average it with viewpoint 1's
  refused(map.view(0), shorter);
  views::ReferenceView without = map.view(0);
  without.planes.erase("texture");
  refused(without, map.model(0));
}

TEST(IlluminationMap, ANewObjectStandsOutAndANewShadowDoesNot) {
  const IlluminationMap map = Learnt();
  const NewObject object{{0.25, -0.15, 0.15, 0.15}, {0.6, 0.2, 0.2}};
  cv::Mat truth, shadow;
  const core::Frame frame =
      Render(0.11, {1.1, {-0.05, 0.25}, 0.15}, 2000, &object, &truth, nullptr, &shadow);
  const IlluminationMapResult r = map.Detect(frame);
  ASSERT_GT(r.coverage, 0.9);
  const cv::Mat background = ~truth & ~shadow & r.viewpoint.covered;
  const double on_object = cv::mean(r.novelty.novelty, truth & r.viewpoint.covered)[0];
  const double on_shadow = cv::mean(r.novelty.novelty, shadow & r.viewpoint.covered)[0];
  const double elsewhere = cv::mean(r.novelty.novelty, background)[0];
  EXPECT_GT(on_object, 3.0 * elsewhere) << on_object << " vs " << elsewhere;
  EXPECT_GT(on_object, on_shadow) << on_object << " vs shadow " << on_shadow;
  EXPECT_TRUE(cv::checkRange(r.novelty.novelty));
}

// Share of the covered pixels of `mask` with Δ above τ.
double ShareAboveThreshold(const IlluminationMapResult& r, const cv::Mat& mask, double tau) {
  const cv::Mat judged = mask & r.viewpoint.covered;
  return cv::countNonZero((r.novelty.novelty > tau) & judged) / double(cv::countNonZero(judged));
}

TEST(IlluminationMap, TheThresholdFromTrainingLightingsHoldsOnUnseenOnes) {
  const IlluminationMap map = Learnt();
  const double tau = map.decision_threshold();
  ASSERT_TRUE(std::isfinite(tau));
  // Unseen lightings with shadows of their own, nothing new: the target false-alarm rate (1 %),
  // with room for the few frames judged.
  const std::vector<Lighting> unseen = {
      {1.1, {-0.05, 0.25}}, {0.85, {0.30, 0.05}}, {1.25, {0.15, -0.30}}};
  long alarms = 0, judged = 0;
  for (std::size_t k = 0; k < unseen.size(); ++k) {
    const IlluminationMapResult r = map.Detect(Render(0.07 + 0.05 * k, unseen[k], 4000 + int(k)));
    alarms += cv::countNonZero((r.novelty.novelty > tau) & r.viewpoint.covered);
    judged += cv::countNonZero(r.viewpoint.covered);
    // Detect's own decision is the same pixels.
    EXPECT_EQ(cv::countNonZero(r.novel != ((r.novelty.novelty > tau) & r.viewpoint.covered)), 0);
    EXPECT_NEAR(r.novel_share,
                cv::countNonZero(r.novel) / double(cv::countNonZero(r.viewpoint.covered)), 1e-12);
  }
  EXPECT_LE(double(alarms) / double(judged), 0.02) << alarms << " of " << judged << ", tau " << tau;
  // A new object under an unseen lighting: most of it above τ.
  const NewObject object{{0.25, -0.15, 0.15, 0.15}, {0.6, 0.2, 0.2}};
  cv::Mat truth;
  const IlluminationMapResult r =
      map.Detect(Render(0.11, {1.1, {-0.05, 0.25}, 0.15}, 4100, &object, &truth));
  EXPECT_GE(ShareAboveThreshold(r, truth, tau), 0.5);
}

TEST(IlluminationMap, NoThresholdWithoutALightingToLeaveOut) {
  IlluminationMapOptions options;
  options.invariant.min_lightings = 2;
  IlluminationMap two(options);
  for (int m = 0; m < 2; ++m) {
    two.BeginLighting();
    for (int k = 0; k <= 5; ++k) two.AddTrainingFrame(Render(0.02 * k, kLightings[m], 10 * m + k));
  }
  two.Build();
  EXPECT_TRUE(std::isnan(two.decision_threshold()));
  const IlluminationMapResult undecided = two.Detect(Render(0.05, kLightings[2], 99));
  EXPECT_GT(undecided.coverage, 0.5);
  EXPECT_TRUE(undecided.novel.empty());
  EXPECT_TRUE(std::isnan(undecided.novel_share));
  options.threshold.viewpoints = 0;
  EXPECT_TRUE(std::isnan(Learnt(options).decision_threshold()));
  options.threshold.false_alarm_rate = 0.0;
  EXPECT_THROW(IlluminationMap{options}, std::invalid_argument);
  IlluminationMap loaded;
  EXPECT_THROW(loaded.SetDecisionThreshold(-1.0), std::invalid_argument);
  loaded.SetDecisionThreshold(4.5);
  EXPECT_EQ(loaded.decision_threshold(), 4.5);
}

TEST(IlluminationMap, AFrameNoViewpointFacesHasNoCoverage) {
  const IlluminationMap map = Learnt();
  core::Frame frame = Render(0.1, kLightings[0], 3000);
  frame.T_world_cam = Eigen::Isometry3d(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitY()));
  const IlluminationMapResult r = map.Detect(frame);
  EXPECT_EQ(r.coverage, 0.0);
  EXPECT_TRUE(r.viewpoints.empty());
  EXPECT_TRUE(r.novelty.novelty.empty());
}

TEST(IlluminationMap, BadInputIsAClearError) {
  IlluminationMap one;
  one.BeginLighting();
  for (int k = 0; k < 3; ++k) one.AddTrainingFrame(Render(0.02 * k, kLightings[0], k + 1));
  EXPECT_THROW(one.Build(), std::invalid_argument);  // a single lighting

  IlluminationMap map;
  EXPECT_THROW(map.Detect(Render(0, kLightings[0], 1)), std::logic_error);  // before Build
  core::Frame no_pose = Render(0, kLightings[0], 7);
  no_pose.T_world_cam.reset();
  try {
    map.AddTrainingFrame(no_pose);
    FAIL() << "a frame without pose was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("frame 7"), std::string::npos) << e.what();
  }
  core::Frame no_depth = Render(0, kLightings[0], 8);
  no_depth.depth.release();
  EXPECT_THROW(map.AddTrainingFrame(no_depth), std::invalid_argument);
  map.AddTrainingFrame(Render(0, kLightings[0], 9));
  core::Frame small = Render(0, kLightings[0], 10);
  small.camera.width = 80;
  cv::resize(small.rgb, small.rgb, {80, 120});
  cv::resize(small.depth, small.depth, {80, 120});
  EXPECT_THROW(map.AddTrainingFrame(small), std::invalid_argument);
  map.BeginLighting();
  EXPECT_THROW(map.BeginLighting(), std::invalid_argument);  // lighting 1 had no frames

  const IlluminationMap built = Learnt();
  core::Frame wrong_size = Render(0, kLightings[0], 11);
  cv::resize(wrong_size.rgb, wrong_size.rgb, {80, 60});
  EXPECT_THROW(built.Detect(wrong_size), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::illumination
