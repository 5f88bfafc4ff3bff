#include "maps/illumination/illumination_novelty.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace novelty::illumination {
namespace {

// A textured scene under six lights of different strength; a highlight (light × 3) on an
// ellipse — the plate — in images 1 and 4, so that the highlight is a minority at every pixel.
struct Scene {
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

Scene MakeScene() {
  Scene s;
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

TEST(IlluminationNovelty, AKnownHighlightIsDampedAndANewObjectStandsOut) {
  const Scene scene = MakeScene();
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
  const Scene scene = MakeScene();
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
  Scene scene = MakeScene();
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
  const Scene scene = MakeScene();
  const InvariantImage invariant = ComputeInvariantImage(scene.training);
  ViewpointIllumination viewpoint = MakeViewpoint(invariant, LearnIlluminationModel(invariant));
  cv::Mat corner = cv::Mat::zeros(scene.highlight.size(), CV_8U);
  cv::circle(corner, {72, 52}, 12, cv::Scalar(255), cv::FILLED);  // touches the ellipse's end
  viewpoint.shapes = {{cv::boundingRect(corner), corner(cv::boundingRect(corner)).clone(), {}}};
  const IlluminationNovelty n =
      DetectIlluminationNovelty(scene.Lit(0.9, true), viewpoint, ZernikeMoments());
  EXPECT_EQ(n.matched_count, 0);
}

TEST(IlluminationNovelty, RejectsAFrameOfAnotherSize) {
  const Scene scene = MakeScene();
  const InvariantImage invariant = ComputeInvariantImage(scene.training);
  const ViewpointIllumination viewpoint =
      MakeViewpoint(invariant, LearnIlluminationModel(invariant));
  EXPECT_THROW(DetectIlluminationNovelty(cv::Mat::zeros(10, 10, CV_32FC3), viewpoint,
                                         ZernikeMoments({8, 16})),
               std::invalid_argument);
}

}  // namespace
}  // namespace novelty::illumination
