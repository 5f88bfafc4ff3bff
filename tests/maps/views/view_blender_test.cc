#include "maps/views/view_blender.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace novelty::views {
namespace {

// The thesis's plain average, which most tests check (the defaults weight views).
const BlendOptions kThesis = BlendOptions::ThesisAverage();

// A warp field that maps each virtual pixel of the left `covered` columns to itself at `depth`.
WarpField Field(int width, int height, int covered, float depth) {
  WarpField w;
  w.depth = cv::Mat(height, width, CV_32FC1, cv::Scalar(0));
  w.source_depth = cv::Mat(height, width, CV_32FC1, cv::Scalar(0));
  w.map = cv::Mat(height, width, CV_32FC2, cv::Scalar(-1, -1));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < covered; ++x) {
      w.depth.at<float>(y, x) = w.source_depth.at<float>(y, x) = depth;
      w.map.at<cv::Vec2f>(y, x) = cv::Vec2f(float(x), float(y));
    }
  }
  w.covered = covered * height;
  return w;
}

TEST(ViewBlender, AveragesValidContributionsAndMarksUncoveredPixels) {
  const std::vector<WarpField> warps = {Field(8, 4, 6, 2.0f), Field(8, 4, 3, 2.0f)};
  const std::vector<cv::Mat> planes = {cv::Mat(4, 8, CV_8UC1, cv::Scalar(10)),
                                       cv::Mat(4, 8, CV_8UC1, cv::Scalar(30))};
  const BlendResult r = BlendPlanes(warps, planes, kThesis);
  EXPECT_FLOAT_EQ(r.value.at<float>(1, 1), 20.0f);   // both views
  EXPECT_FLOAT_EQ(r.value.at<float>(1, 4), 10.0f);   // first view only
  EXPECT_TRUE(std::isnan(r.value.at<float>(1, 7)));  // nobody: invalid, not zero
  EXPECT_EQ(r.valid.at<uint8_t>(1, 7), 0);
  EXPECT_EQ(r.covered, 6 * 4);
}

TEST(ViewBlender, MultiChannelViewsAverageWhereTheyCover) {
  // 20 columns (a sixteen-pixel group and a tail); the first view covers 18, the second 5. Seven
  // half-float and three float channels, as the appearance map's parameter planes.
  const std::vector<WarpField> warps = {Field(20, 3, 18, 2.0f), Field(20, 3, 5, 2.0f)};
  for (const int type : {CV_16FC(7), CV_32FC3}) {
    std::vector<cv::Mat> planes;
    for (const float value : {10.0f, 30.0f}) {  // (cv::Scalar fills at most 4 channels)
      cv::Mat plane;
      cv::Mat(3, 20 * CV_MAT_CN(type), CV_32FC1, cv::Scalar(value))
          .reshape(CV_MAT_CN(type))
          .convertTo(plane, CV_MAT_DEPTH(type));
      planes.push_back(plane);
    }
    const BlendResult r = BlendPlanes(warps, planes, kThesis);
    ASSERT_EQ(r.covered, 18 * 3);
    for (int c = 0; c < r.value.channels(); ++c) {
      EXPECT_FLOAT_EQ(r.value.ptr<float>(2)[4 * r.value.channels() + c], 20.0f) << c;
      EXPECT_FLOAT_EQ(r.value.ptr<float>(2)[5 * r.value.channels() + c], 10.0f) << c;
      EXPECT_FLOAT_EQ(r.value.ptr<float>(2)[17 * r.value.channels() + c], 10.0f) << c;
      EXPECT_TRUE(std::isnan(r.value.ptr<float>(1)[18 * r.value.channels() + c])) << c;
    }
    EXPECT_EQ(r.valid.at<uint8_t>(0, 17), 255);
    EXPECT_EQ(r.valid.at<uint8_t>(0, 18), 0);
  }
}

TEST(ViewBlender, WeightsAndDepthToleranceChangeTheMix) {
  const std::vector<cv::Mat> planes = {cv::Mat(2, 4, CV_32FC1, cv::Scalar(10)),
                                       cv::Mat(2, 4, CV_32FC1, cv::Scalar(30))};
  BlendOptions weighted = kThesis;
  weighted.weights = {3.0, 1.0};
  const std::vector<WarpField> same = {Field(4, 2, 4, 2.0f), Field(4, 2, 4, 2.0f)};
  EXPECT_FLOAT_EQ(BlendPlanes(same, planes, weighted).value.at<float>(0, 0), 15.0f);
  // The second view sees a surface 50 % behind the first's: with a tolerance it is left out.
  const std::vector<WarpField> occluded = {Field(4, 2, 4, 2.0f), Field(4, 2, 4, 3.0f)};
  BlendOptions tolerant = kThesis;
  tolerant.depth_tolerance = 0.05;
  EXPECT_FLOAT_EQ(BlendPlanes(occluded, planes, kThesis).value.at<float>(0, 0), 20.0f);
  EXPECT_FLOAT_EQ(BlendPlanes(occluded, planes, tolerant).value.at<float>(0, 0), 10.0f);
}

TEST(ViewBlender, MultiChannelPlanesKeepTheirChannels) {
  const std::vector<WarpField> warps = {Field(4, 2, 4, 1.0f)};
  const std::vector<cv::Mat> planes = {cv::Mat(2, 4, CV_8UC3, cv::Scalar(1, 2, 3))};
  const BlendResult r = BlendPlanes(warps, planes, kThesis);
  ASSERT_EQ(r.value.type(), CV_32FC3);
  EXPECT_EQ(r.value.at<cv::Vec3f>(1, 2), cv::Vec3f(1, 2, 3));
}

TEST(ViewBlender, BilinearSamplesAreExactForLinearPlanesOfEveryDepth) {
  // 40 columns: two sixteen-pixel groups and a tail of eight, so both kernel forms run. The map
  // samples between pixels; a plane linear in x and y is reproduced exactly by bilinear
  // interpolation, clamped at the border (u ≤ 39, v ≤ 19: the last pixel is read). 8-bit planes
  // take the in-place word path (1 and 3 channels: the last pixels' words are shifted), half-float
  // planes the in-place path (2 and 7 channels: whole words, and an odd last one); with AVX-512 or
  // AVX2, half and float planes of 2–8 channels are read a pixel at a time (8: every bit of the
  // channel mask); 10 float channels take two passes.
  const int w = 40, h = 20;
  WarpField f = Field(w, h, w, 2.0f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) f.map.at<cv::Vec2f>(y, x) = cv::Vec2f(x + 0.25f, y + 0.5f);
  const std::pair<int, int> cases[] = {
      {CV_8U, 1},  {CV_8U, 3},  {CV_8U, 4},  {CV_16F, 2}, {CV_16F, 3},  {CV_16F, 7}, {CV_16F, 8},
      {CV_32F, 2}, {CV_32F, 3}, {CV_32F, 7}, {CV_32F, 8}, {CV_32F, 10}, {CV_16U, 3}};
  for (const auto& [depth, channels] : cases) {
    cv::Mat linear(h, w, CV_32FC(channels));
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < channels; ++c)
          linear.ptr<float>(y)[x * channels + c] = 2.0f * x + 3.0f * y + 25.0f * c;
    cv::Mat plane;
    linear.convertTo(plane, depth);
    const BlendResult r = BlendPlanes({f}, {plane}, kThesis);
    ASSERT_EQ(r.covered, w * h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < channels; ++c) {
          const float u = std::min(x + 0.25f, float(w - 1)), v = std::min(y + 0.5f, float(h - 1));
          ASSERT_NEAR(r.value.ptr<float>(y)[x * channels + c], 2.0f * u + 3.0f * v + 25.0f * c,
                      1e-3)
              << "depth " << depth << ", " << channels << " channels, at " << x << "," << y
              << " channel " << c;
        }
  }
}

TEST(ViewBlender, BilinearSamplesAreExactWhereViewsAreTurnedOrMagnified) {
  // Maps as a turned or magnified view gives them: the sixteen pixels of a group read source rows
  // that slant across one, two or many rows, or columns further apart than one window holds, so
  // 8-bit planes take every read path (the narrow rows, the windows, the gathers); half and float
  // planes are read a pixel at a time. A plane linear in x and y is still reproduced exactly,
  // clamped at the border.
  const int w = 48, h = 24;
  struct Map {
    float ux, uy, u0, vx, vy, v0;
  };
  const Map maps[] = {{1.0f, 0.0f, 0.25f, 0.0f, 1.0f, 0.5f},      // aligned
                      {0.95f, 0.1f, 0.3f, 0.07f, 0.9f, 0.6f},     // slightly turned: one row
                      {0.9f, 0.2f, 0.1f, 0.2f, 0.8f, 0.4f},       // turned: rows 3 apart
                      {0.6f, 0.5f, 0.7f, 0.55f, 0.4f, 0.2f},      // turned far
                      {2.3f, 0.0f, 0.4f, 0.0f, 1.1f, 0.3f},       // magnified: wide columns
                      {-0.9f, 0.0f, 46.5f, 0.0f, -1.0f, 23.2f}};  // mirrored
  for (const Map& m : maps) {
    WarpField f = Field(w, h, w, 2.0f);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        f.map.at<cv::Vec2f>(y, x) =
            cv::Vec2f(m.ux * x + m.uy * y + m.u0, m.vx * x + m.vy * y + m.v0);
    const std::pair<int, int> cases[] = {{CV_8U, 1},  {CV_8U, 3},  {CV_8U, 4},
                                         {CV_16F, 7}, {CV_32F, 3}, {CV_32F, 8}};
    for (const auto& [depth, channels] : cases) {
      cv::Mat linear(h, w, CV_32FC(channels)), plane;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          for (int c = 0; c < channels; ++c)
            linear.ptr<float>(y)[x * channels + c] = float(2 * x + 3 * y + 25 * c);
      linear.convertTo(plane, depth);
      const BlendResult r = BlendPlanes({f}, {plane}, kThesis);
      ASSERT_EQ(r.covered, w * h);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const cv::Vec2f s = f.map.at<cv::Vec2f>(y, x);
          const float u = std::clamp(s[0], 0.0f, float(w - 1));
          const float v = std::clamp(s[1], 0.0f, float(h - 1));
          for (int c = 0; c < channels; ++c)
            ASSERT_NEAR(r.value.ptr<float>(y)[x * channels + c], 2.0f * u + 3.0f * v + 25.0f * c,
                        1e-3)
                << "map " << (&m - maps) << ", depth " << depth << ", " << channels
                << " channels, at " << x << "," << y << " channel " << c;
        }
    }
  }
}

TEST(ViewBlender, PlanesOfDifferentDepthsOrLayoutsBlendAlike) {
  // One 8-bit view, one float view, one 8-bit view cut from a larger image (not continuous): the
  // kernel reads all three as floats.
  const std::vector<WarpField> warps = {Field(20, 3, 20, 1.0f), Field(20, 3, 20, 1.0f),
                                        Field(20, 3, 20, 1.0f)};
  const cv::Mat larger(5, 30, CV_8UC3, cv::Scalar(40, 50, 60));
  const std::vector<cv::Mat> planes = {cv::Mat(3, 20, CV_8UC3, cv::Scalar(10, 20, 30)),
                                       cv::Mat(3, 20, CV_32FC3, cv::Scalar(31, 41, 51)),
                                       larger(cv::Rect(2, 1, 20, 3))};
  const BlendResult r = BlendPlanes(warps, planes, kThesis);
  ASSERT_EQ(r.covered, 60);
  for (int x : {0, 17, 19}) EXPECT_EQ(r.value.at<cv::Vec3f>(2, x), cv::Vec3f(27, 37, 47)) << x;
}

TEST(ViewBlender, RowsBlendedInPartsEqualTheWholeBlend) {
  // A turned view and a partly uncovered one; half, float and 8-bit planes; 37 columns (two
  // groups of sixteen and a tail); the parts in any order.
  std::vector<WarpField> warps = {Field(37, 9, 37, 1.0f), Field(37, 9, 30, 1.0f)};
  for (int y = 0; y < 9; ++y)
    for (int x = 0; x < 30; ++x)
      warps[1].map.at<cv::Vec2f>(y, x) = cv::Vec2f(0.9f * x + 0.3f * y + 1.2f, 0.2f * x + 0.7f * y);
  cv::RNG rng(11);
  for (const auto& [depth, channels] :
       std::vector<std::pair<int, int>>{{CV_16F, 7}, {CV_32F, 3}, {CV_8U, 3}}) {
    std::vector<cv::Mat> planes;
    for (int k = 0; k < 2; ++k) {
      cv::Mat values(20, 40, CV_32FC(channels)), plane;
      rng.fill(values, cv::RNG::UNIFORM, 0.0, 200.0);
      values.convertTo(plane, depth);
      planes.push_back(plane);
    }
    const BlendResult whole = BlendPlanes(warps, planes, kThesis);
    BlendResult parts;
    PrepareBlend(warps, planes, kThesis, parts);
    int covered = 0;
    for (const cv::Range rows : {cv::Range(6, 9), cv::Range(0, 2), cv::Range(2, 6)}) {
      covered += BlendRows(warps, planes, kThesis, rows, parts);
    }
    EXPECT_EQ(covered, whole.covered);
    EXPECT_EQ(covered, 37 * 9);
    EXPECT_EQ(cv::norm(parts.value, whole.value, cv::NORM_INF), 0.0) << depth << " " << channels;
    EXPECT_EQ(cv::norm(parts.valid, whole.valid, cv::NORM_INF), 0.0);
  }
  // Rows outside the result, or a result not prepared for these planes.
  const std::vector<cv::Mat> planes = {cv::Mat(20, 40, CV_32FC3), cv::Mat(20, 40, CV_32FC3)};
  BlendResult r;
  EXPECT_THROW(BlendRows(warps, planes, kThesis, cv::Range(0, 2), r), std::invalid_argument);
  PrepareBlend(warps, planes, kThesis, r);
  EXPECT_THROW(BlendRows(warps, planes, kThesis, cv::Range(8, 10), r), std::invalid_argument);
  const std::vector<cv::Mat> one_channel = {cv::Mat(20, 40, CV_32FC1), cv::Mat(20, 40, CV_32FC1)};
  EXPECT_THROW(BlendRows(warps, one_channel, kThesis, cv::Range(0, 2), r), std::invalid_argument);
  EXPECT_THROW(BlendRows(warps, {planes[0]}, kThesis, cv::Range(0, 2), r), std::invalid_argument);
  EXPECT_EQ(BlendRows(warps, planes, kThesis, cv::Range(3, 3), r), 0);
}

TEST(ViewBlender, AKeptResultIsWrittenInPlaceUnlessSomeoneElseHoldsIt) {
  const std::vector<WarpField> warps = {Field(20, 3, 20, 1.0f)};
  const std::vector<cv::Mat> tens = {cv::Mat(3, 20, CV_8UC3, cv::Scalar(10, 10, 10))};
  const std::vector<cv::Mat> twenties = {cv::Mat(3, 20, CV_8UC3, cv::Scalar(20, 20, 20))};
  BlendResult kept;
  BlendPlanes(warps, tens, kThesis, kept);
  const uchar* data = kept.value.data;
  BlendPlanes(warps, twenties, kThesis, kept);  // nobody else holds it: the same images
  EXPECT_EQ(kept.value.data, data);
  EXPECT_EQ(kept.value.at<cv::Vec3f>(2, 19), cv::Vec3f(20, 20, 20));
  EXPECT_EQ(kept.covered, 60);
  const cv::Mat held = kept.value, held_valid = kept.valid;  // a caller keeps the last frame's
  BlendPlanes(warps, tens, kThesis, kept);
  EXPECT_NE(kept.value.data, held.data);
  EXPECT_NE(kept.valid.data, held_valid.data);
  EXPECT_EQ(held.at<cv::Vec3f>(2, 19), cv::Vec3f(20, 20, 20));  // untouched
  EXPECT_EQ(kept.value.at<cv::Vec3f>(2, 19), cv::Vec3f(10, 10, 10));
  // Another size or channel count: allocated to fit.
  BlendPlanes({Field(8, 2, 8, 1.0f)}, {cv::Mat(2, 8, CV_32FC1, cv::Scalar(5))}, kThesis, kept);
  EXPECT_EQ(kept.value.type(), CV_32FC1);
  EXPECT_EQ(kept.value.size(), cv::Size(8, 2));
  EXPECT_FLOAT_EQ(kept.value.at<float>(1, 7), 5.0f);
}

TEST(ViewBlender, MismatchedInputIsRejected) {
  const std::vector<WarpField> warps = {Field(4, 2, 4, 1.0f)};
  EXPECT_THROW(BlendPlanes(warps, {}, kThesis), std::invalid_argument);
  BlendOptions o = kThesis;
  o.weights = {1.0, 2.0};
  EXPECT_THROW(BlendPlanes(warps, {cv::Mat(2, 4, CV_8UC1)}, o), std::invalid_argument);
  // resolution_power needs the source depth, which a warp fills only when asked.
  std::vector<WarpField> no_source_depth = {Field(4, 2, 4, 1.0f)};
  no_source_depth[0].source_depth.release();
  BlendOptions resolution = kThesis;
  resolution.resolution_power = 1.0;
  EXPECT_THROW(BlendPlanes(no_source_depth, {cv::Mat(2, 4, CV_8UC1)}, resolution),
               std::invalid_argument);
  EXPECT_NO_THROW(BlendPlanes(warps, {cv::Mat(2, 4, CV_8UC1)}, resolution));
  // depth_tolerance needs the depth, which a warp fills only when asked; the plain average not.
  std::vector<WarpField> map_only = {Field(4, 2, 4, 1.0f)};
  map_only[0].depth.release();
  map_only[0].source_depth.release();
  BlendOptions tolerant = kThesis;
  tolerant.depth_tolerance = 0.05;
  EXPECT_THROW(BlendPlanes(map_only, {cv::Mat(2, 4, CV_8UC1)}, tolerant), std::invalid_argument);
  EXPECT_EQ(
      BlendPlanes(map_only, {cv::Mat(2, 4, CV_8UC1, cv::Scalar(7))}, kThesis).value.at<float>(1, 3),
      7.0f);
}

// Angle weights are relative to the pixel's best view: cos φ^10000 underflows to 0 for views a
// few degrees off (cos 0.9: 0.9^10000 = 0 in float and double), which must not uncover pixels
// that views cover. 16 + 3 columns: the sixteen-pixel kernel and the one-pixel tail.
TEST(ViewBlender, AngleWeightsRankViewsButNeverUncoverAPixel) {
  const int width = 19, height = 2;
  std::vector<WarpField> warps = {Field(width, height, width, 2.0f),
                                  Field(width, height, width, 2.0f)};
  warps[0].cos_angle = cv::Mat(height, width, CV_32FC1, cv::Scalar(0.90f));
  warps[1].cos_angle = cv::Mat(height, width, CV_32FC1, cv::Scalar(0.95f));
  warps[1].map.colRange(10, width).setTo(cv::Scalar(-1, -1));  // view 1 covers columns 0–9
  const std::vector<cv::Mat> planes = {cv::Mat(height, width, CV_8UC1, cv::Scalar(10)),
                                       cv::Mat(height, width, CV_8UC1, cv::Scalar(30))};
  BlendOptions o = kThesis;
  o.angle_power = 10000.0;
  const BlendResult r = BlendPlanes(warps, planes, o);
  EXPECT_EQ(r.covered, width * height) << "every pixel some view covers stays covered";
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      // Where both cover, view 1 (5° nearer the virtual ray) dominates: (0.90/0.95)^10000 ≈ 0.
      EXPECT_FLOAT_EQ(r.value.at<float>(y, x), x < 10 ? 30.0f : 10.0f) << x << "," << y;
    }
  }
  // Power 20: the weights (cos φ / cos φ_best)^20 — view 0 gets (0.90/0.95)^20 = 0.3392.
  o.angle_power = 20.0;
  const double w0 = std::pow(0.90 / 0.95, 20.0);
  const BlendResult soft = BlendPlanes(warps, planes, o);
  EXPECT_NEAR(soft.value.at<float>(0, 3), (10.0 * w0 + 30.0) / (w0 + 1.0), 1e-3);
  EXPECT_NEAR(soft.value.at<float>(1, 17), 10.0, 1e-5);
}

TEST(ViewBlender, WarpOutputsForAskForWhatTheBlendReads) {
  const WarpOutputs plain = WarpOutputsFor(kThesis);
  EXPECT_FALSE(plain.depth);
  EXPECT_FALSE(plain.source_depth);
  EXPECT_FALSE(plain.view_angles);
  BlendOptions b = kThesis;
  b.depth_tolerance = 0.03;
  EXPECT_TRUE(WarpOutputsFor(b).depth);
  b = kThesis;
  b.resolution_power = 1.0;
  EXPECT_TRUE(WarpOutputsFor(b).depth);
  EXPECT_TRUE(WarpOutputsFor(b).source_depth);
  b = kThesis;
  b.angle_power = 2.0;
  EXPECT_TRUE(WarpOutputsFor(b).depth);
  EXPECT_TRUE(WarpOutputsFor(b).view_angles);
}

}  // namespace
}  // namespace novelty::views
