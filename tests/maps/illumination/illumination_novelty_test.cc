#include "maps/illumination/illumination_novelty.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include <opencv2/imgproc.hpp>

namespace novelty::illumination {
namespace {

// A textured scene under six lights of different strength; a highlight (light × 3) on an
// ellipse — the plate — in images 1 and 4, so that the highlight is a minority at every pixel.
struct NoveltyScene {
  cv::Mat reflectance, highlight;
  std::vector<cv::Mat> training;
  cv::Mat Lit(double light, bool with_highlight) const {
    cv::Mat lighting(reflectance.size(), CV_32FC3, cv::Scalar::all(light));
    if (with_highlight) lighting.setTo(cv::Scalar::all(3.0 * light), highlight);
    cv::Mat out = reflectance.mul(lighting), noise(out.size(), out.type());
    cv::RNG(int(light * 1000)).fill(noise, cv::RNG::UNIFORM, -0.5, 0.5);
    return out + noise;
  }
};

NoveltyScene MakeNoveltyScene() {
  NoveltyScene s;
  s.reflectance.create(120, 160, CV_32FC3);
  cv::RNG(5).fill(s.reflectance, cv::RNG::UNIFORM, 30, 80);
  cv::GaussianBlur(s.reflectance, s.reflectance, {0, 0}, 2.0);
  s.highlight = cv::Mat::zeros(s.reflectance.size(), CV_8U);
  cv::ellipse(s.highlight, {50, 40}, {18, 9}, 25.0, 0, 360, cv::Scalar(255), cv::FILLED);
  for (int m = 0; m < 6; ++m) s.training.push_back(s.Lit(0.8 + 0.08 * m, m == 1 || m == 4));
  return s;
}

double MeanIn(const cv::Mat& values, const cv::Mat& mask) {
  return cv::mean(values, mask)[0];
}

// The share of `positive` pixels above the 99th percentile of the `negative` ones: the TPR at a
// false-positive rate of 1 %.
double FoundAtOnePercent(const cv::Mat& values, const cv::Mat& positive, const cv::Mat& negative) {
  std::vector<float> neg;
  for (int i = 0; i < int(values.total()); ++i)
    if (negative.data[i]) neg.push_back(values.ptr<float>()[i]);
  std::nth_element(neg.begin(), neg.begin() + long(neg.size() * 0.99), neg.end());
  const float threshold = neg[std::size_t(neg.size() * 0.99)];
  return cv::countNonZero((values > threshold) & positive) / double(cv::countNonZero(positive));
}

TEST(IlluminationNovelty, AKnownHighlightIsDampedAndANewObjectStandsOut) {
  const NoveltyScene scene = MakeNoveltyScene();
  const InvariantImage invariant = ComputeInvariantImage(scene.training);
  const ViewpointIllumination viewpoint =
      MakeViewpoint(invariant, LearnIlluminationModel(invariant));
  ASSERT_GE(viewpoint.shapes.size(), 1u);  // the highlight was stored
  // A new frame: the highlight again, and a new dark-red object (reflectance × (0.6, 0.2, 0.2)).
  cv::Mat frame = scene.Lit(0.9, true);
  cv::Mat object = cv::Mat::zeros(frame.size(), CV_8U);
  object(cv::Rect(100, 70, 24, 24)).setTo(255);
  cv::Mat dimmed = frame.mul(cv::Mat(frame.size(), CV_32FC3, cv::Scalar(0.6, 0.2, 0.2)));
  dimmed.copyTo(frame, object);
  const ZernikeMoments zernike;
  const IlluminationNovelty n = DetectIlluminationNovelty(frame, viewpoint, zernike);
  EXPECT_GE(n.region_count, 1);
  EXPECT_GE(n.matched_count, 1);
  // The highlight matches its stored shape: damped to under a third of the object's novelty.
  const double on_highlight = MeanIn(n.novelty, scene.highlight);
  const double on_object = MeanIn(n.novelty, object);
  EXPECT_LT(on_highlight, on_object / 3.0) << on_highlight << " vs " << on_object;
  EXPECT_LT(MeanIn(n.shape_factor, scene.highlight), 0.5);
  EXPECT_TRUE(cv::checkRange(n.novelty));
}

TEST(IlluminationNovelty, WithoutTheShapeMemoryTheHighlightIsAsNovelAsTheObject) {
  // The same frame against a viewpoint that stored no shapes: nothing damps the highlight,
  // which is the contrast the shape memory exists for.
  const NoveltyScene scene = MakeNoveltyScene();
  const InvariantImage invariant = ComputeInvariantImage(scene.training);
  ViewpointIllumination viewpoint = MakeViewpoint(invariant, LearnIlluminationModel(invariant));
  viewpoint.shapes.clear();
  const cv::Mat frame = scene.Lit(0.9, true);
  const IlluminationNovelty n =
      DetectIlluminationNovelty(frame, viewpoint, ZernikeMoments({40, 32}));
  EXPECT_EQ(n.matched_count, 0);
  EXPECT_GT(MeanIn(n.shape_factor, scene.highlight), 0.9);
}

TEST(IlluminationNovelty, AloneInItsFrameAKnownHighlightIsDampedOnlyAgainstTheEmptyShape) {
  // The frame holds the highlight, a little larger than stored (the lamp moved), and nothing
  // else new. With ê the frame's largest e (the thesis) its own e is ê: e/ê = 1, no damping at
  // all. Against its distance to the empty shape, the stored shape explains it far better than
  // nothing: damped.
  NoveltyScene scene = MakeNoveltyScene();
  const InvariantImage invariant = ComputeInvariantImage(scene.training);
  const ZernikeMoments zernike;
  const ViewpointIllumination viewpoint =
      MakeViewpoint(invariant, LearnIlluminationModel(invariant), 16, &zernike);
  cv::ellipse(scene.highlight, {50, 40}, {20, 10}, 25.0, 0, 360, cv::Scalar(255), cv::FILLED);
  const cv::Mat frame = scene.Lit(0.9, true);
  IlluminationNoveltyOptions options;
  const IlluminationNovelty thesis = DetectIlluminationNovelty(frame, viewpoint, zernike, options);
  ASSERT_GE(thesis.matched_count, 1);
  options.shape_scale = IlluminationNoveltyOptions::ShapeScale::kEmptyShape;
  const IlluminationNovelty empty = DetectIlluminationNovelty(frame, viewpoint, zernike, options);
  EXPECT_GT(MeanIn(thesis.shape_factor, scene.highlight), 0.9);
  EXPECT_LT(MeanIn(empty.shape_factor, scene.highlight), 0.5);
}

TEST(IlluminationNovelty, ASliverOfOverlapIsNoMatch) {
  // A stored shape that meets the new region in a corner only (a few percent of either): scaled
  // to the unit disc the two slivers would look alike, but they say nothing about the shapes.
  const NoveltyScene scene = MakeNoveltyScene();
  const InvariantImage invariant = ComputeInvariantImage(scene.training);
  ViewpointIllumination viewpoint = MakeViewpoint(invariant, LearnIlluminationModel(invariant));
  cv::Mat corner = cv::Mat::zeros(scene.highlight.size(), CV_8U);
  cv::circle(corner, {72, 52}, 12, cv::Scalar(255), cv::FILLED);  // touches the ellipse's end
  viewpoint.shapes = {{cv::boundingRect(corner), corner(cv::boundingRect(corner)).clone(), {}}};
  const IlluminationNovelty n =
      DetectIlluminationNovelty(scene.Lit(0.9, true), viewpoint, ZernikeMoments());
  EXPECT_EQ(n.matched_count, 0);
}

// Blue and white stripes (the plate scene's cloth) under six lights, one of them with a soft
// shadow, and a new frame with a box coloured like the white stripes on them.
struct StripedScene {
  cv::Mat reflectance, box, box_on_white;
  std::vector<cv::Mat> training;
  cv::Mat Lit(double light, bool shadow) const {
    cv::Mat lighting(reflectance.size(), CV_32FC3, cv::Scalar::all(light));
    if (shadow) {
      cv::Mat dark = cv::Mat::zeros(reflectance.size(), CV_32F);
      cv::circle(dark, {40, 80}, 22, cv::Scalar(0.6f), cv::FILLED);
      cv::GaussianBlur(dark, dark, {0, 0}, 3.0);
      cv::Mat dark3;
      cv::merge(std::vector<cv::Mat>(3, dark), dark3);
      lighting = lighting.mul(cv::Scalar::all(1.0) - dark3);
    }
    cv::Mat out = reflectance.mul(lighting), noise(out.size(), out.type());
    cv::RNG(int(light * 1000) + shadow).fill(noise, cv::RNG::NORMAL, 0.0, 1.0);
    return out + noise;
  }
};

StripedScene MakeStripedScene() {
  StripedScene s;
  s.reflectance.create(120, 160, CV_32FC3);
  cv::Mat white = cv::Mat::zeros(s.reflectance.size(), CV_8U);
  for (int x = 0; x < s.reflectance.cols; ++x) {
    const bool is_white = (x / 6) % 2 == 0;
    s.reflectance.col(x).setTo(is_white ? cv::Scalar(200, 200, 190) : cv::Scalar(80, 100, 180));
    white.col(x).setTo(is_white ? 255 : 0);
  }
  s.box = cv::Mat::zeros(s.reflectance.size(), CV_8U);
  s.box(cv::Rect(96, 40, 36, 30)).setTo(255);
  cv::Mat inner;  // away from the box's outline, where any method sees an edge
  cv::erode(s.box, inner, cv::Mat(), {-1, -1}, 4);
  s.box_on_white = inner & white;
  for (int m = 0; m < 6; ++m) s.training.push_back(s.Lit(0.5 + 0.08 * m, m == 2));
  return s;
}

TEST(IlluminationNovelty, TheMissingTextureFindsABoxColouredLikeTheSurfaceItHides) {
  const StripedScene scene = MakeStripedScene();
  cv::Mat frame = scene.Lit(0.7, true);
  const cv::Mat box_colour(frame.size(), CV_32FC3, cv::Scalar(200 * 0.7, 200 * 0.7, 190 * 0.7));
  box_colour.copyTo(frame, scene.box);
  cv::Mat background;
  cv::dilate(scene.box, background, cv::Mat(), {-1, -1}, 8);
  background = background == 0;
  const InvariantImage invariant = ComputeInvariantImage(scene.training);
  const ZernikeMoments zernike;
  // The thesis's Δ: on the white stripes the box has the surface's reflectance, so its
  // illumination image there is plain light: no more novel than the background.
  const IlluminationNovelty thesis = DetectIlluminationNovelty(
      frame, MakeViewpoint(invariant, LearnIlluminationModel(invariant)), zernike);
  const double thesis_found = FoundAtOnePercent(thesis.novelty, scene.box_on_white, background);
  EXPECT_LT(thesis_found, 0.5);
  // With the missing texture the box, which hides the stripes' edges, stands far above the
  // background, the frame's shadow included: a shadow keeps the stripes.
  IlluminationModelOptions options;
  options.missing_texture = true;
  const ViewpointIllumination viewpoint =
      MakeViewpoint(invariant, LearnIlluminationModel(invariant, {}, options));
  ASSERT_FALSE(viewpoint.model.texture.empty());
  const IlluminationNovelty n = DetectIlluminationNovelty(frame, viewpoint, zernike);
  EXPECT_GT(MeanIn(n.information_t, scene.box_on_white), 5.0 * MeanIn(n.information_t, background));
  const double found = FoundAtOnePercent(n.novelty, scene.box_on_white, background);
  std::printf("box on white found at FPR 1 %%: %.3f with the missing texture, %.3f without\n",
              found, thesis_found);
  EXPECT_GE(found, 0.9);
  EXPECT_TRUE(cv::checkRange(n.novelty));
}

TEST(IlluminationNovelty, RejectsAFrameOfAnotherSize) {
  const NoveltyScene scene = MakeNoveltyScene();
  const InvariantImage invariant = ComputeInvariantImage(scene.training);
  const ViewpointIllumination viewpoint =
      MakeViewpoint(invariant, LearnIlluminationModel(invariant));
  EXPECT_THROW(DetectIlluminationNovelty(cv::Mat::zeros(10, 10, CV_32FC3), viewpoint,
                                         ZernikeMoments({8, 16})),
               std::invalid_argument);
}

}  // namespace
}  // namespace novelty::illumination
