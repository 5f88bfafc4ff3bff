#include "maps/objects/feature_extractor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <string>

#include "maps/objects/object_acquisition.h"
#include "tests/maps/objects/graf_frame.h"

namespace novelty::objects {
namespace {

// graf1 (a real photograph) at 320×240 as R, G, B, or empty when the shared data is absent.
cv::Mat Frame() {
  const char* shared = std::getenv("NOVELTY_SHARED_DATA");
  const std::string path = std::string(shared ? shared : "") + "/graf/graf1.png";
  if (!shared || !std::filesystem::exists(path)) return {};
  return GrafFrame(path);
}

// The part of `box` grown by `margin`, clipped to the frame, that every crop
// DetectAndComputeInBox makes holds (aligning its corner only moves it further out).
cv::Rect SureCrop(const cv::Rect& box, int margin, const cv::Size& image) {
  const cv::Point m(margin, margin);
  return cv::Rect(box.tl() - m, box.br() + m) & cv::Rect(cv::Point(0, 0), image);
}

// Whether the descriptor window of `k` — a square of side window_per_size · size, turned any
// way, so within √2 times its half side of the centre — grown by `pad` lies in `rect` or leaves
// it only where the frame ends.
bool InsideTurnedAnyWay(const cv::KeyPoint& k, double window_per_size, const cv::Rect& rect,
                        const cv::Size& image, double pad = 0.0) {
  const double r = 0.5 * window_per_size * k.size * std::sqrt(2.0) + pad;
  return (k.pt.x - r >= rect.x || rect.x == 0) && (k.pt.y - r >= rect.y || rect.y == 0) &&
         (k.pt.x + r <= rect.br().x || rect.br().x == image.width) &&
         (k.pt.y + r <= rect.br().y || rect.br().y == image.height);
}

// The features `e` finds in `box` on a crop with `margin` against those it finds on the whole
// frame with the box as mask.
struct Comparison {
  int inside = 0;      // whole-frame keypoints whose window lies in the crop however it turns
  int missing = 0;     // of them, not returned from the crop
  int returned = 0;    // keypoints from the crop
  int same = 0;        // of them, a whole-frame keypoint at the same place, size and angle
  int matched = 0;     // of those, whose descriptor names the whole-frame one by the ratio test
  double worst = 0.0;  // the largest descriptor distance among the same, relative to its norm
  int clear = 0;       // of the same, those whose window and blur lie in the crop
  double worst_clear = 0.0;  // the largest descriptor distance among those
  int outside = 0;           // keypoints from the crop whose centre is not in the box
};

// One keypoint, up to the rounding a few changed pixels far off cause in its sub-pixel place,
// scale and orientation: far below eq. 5.1's δ = 2 px and the 20° and 1.3× that count a match
// as consistent (keypoint_consistency.h).
bool SameKeypoint(const cv::KeyPoint& a, const cv::KeyPoint& b) {
  return cv::norm(a.pt - b.pt) <= 0.05 && std::abs(a.size - b.size) <= 0.01 * a.size &&
         std::abs(std::remainder(a.angle - b.angle, 360.0f)) <= 1.0;
}

Comparison Compare(FeatureExtractor e, const cv::Mat& rgb, const cv::Rect& box, int margin) {
  const cv::Ptr<cv::Feature2D> f = CreateFeatureExtractor(e);
  const double w = DescriptorWindowPerSize(e);
  std::vector<cv::KeyPoint> whole, crop;
  cv::Mat dw, dc;
  DetectAndComputeInBox(e, *f, rgb, box, -1, whole, dw);
  DetectAndComputeInBox(e, *f, rgb, box, margin, crop, dc);
  Comparison c;
  const cv::Rect sure = SureCrop(box, margin, rgb.size());
  for (const cv::KeyPoint& a : whole) {
    if (!InsideTurnedAnyWay(a, w, sure, rgb.size())) continue;
    ++c.inside;
    c.missing += std::none_of(crop.begin(), crop.end(),
                              [&](const cv::KeyPoint& b) { return SameKeypoint(a, b); });
  }
  c.returned = int(crop.size());
  for (std::size_t j = 0; j < crop.size(); ++j) {
    c.outside += !box.contains(cv::Point(crop[j].pt));
    for (std::size_t i = 0; i < whole.size(); ++i) {
      if (!SameKeypoint(whole[i], crop[j])) continue;
      ++c.same;
      const double d = cv::norm(dw.row(int(i)), dc.row(int(j)));
      c.worst = std::max(c.worst, d / cv::norm(dw.row(int(i))));
      // A scale-space value depends on the pixels within about four of its σ (size / 2).
      if (InsideTurnedAnyWay(crop[j], w, sure, rgb.size(), 2.0 * crop[j].size)) {
        ++c.clear;
        c.worst_clear = std::max(c.worst_clear, d / cv::norm(dw.row(int(i))));
      }
      // The database's ratio test (thesis 5.1: 0.65) against every other whole-frame feature.
      double second = std::numeric_limits<double>::infinity();
      for (int h = 0; h < dw.rows; ++h)
        if (h != int(i)) second = std::min(second, cv::norm(dw.row(h), dc.row(int(j))));
      c.matched += d < 0.65 * second;
      break;
    }
  }
  return c;
}

// Twelve 96 × 80 boxes (an object of a tenth of the frame, as in object_acquisition_benchmark)
// over graf1.
Comparison OverBoxes(FeatureExtractor e, const cv::Mat& rgb, int margin) {
  Comparison sum;
  for (int y = 10; y + 80 <= 240; y += 37)
    for (int x = 13; x + 96 <= 320; x += 41) {
      const Comparison c = Compare(e, rgb, {x, y, 96, 80}, margin);
      sum.inside += c.inside;
      sum.missing += c.missing;
      sum.returned += c.returned;
      sum.same += c.same;
      sum.matched += c.matched;
      sum.worst = std::max(sum.worst, c.worst);
      sum.clear += c.clear;
      sum.worst_clear = std::max(sum.worst_clear, c.worst_clear);
      sum.outside += c.outside;
    }
  std::printf(
      "%s, margin %d: %d keypoints from the crop, %d of them the whole frame's, %d matched, "
      "descriptors within %.4f of their norm (%.6f for the %d clear of its edge); %d of %d with "
      "their window in it missing\n",
      FeatureExtractorName(e).c_str(), margin, sum.returned, sum.same, sum.matched, sum.worst,
      sum.worst_clear, sum.clear, sum.missing, sum.inside);
  return sum;
}

// Eq. 5.2's bound: a descriptor this near (relative to its norm) is the same feature.
const double kSameFeature = ObjectAcquisitionOptions().relative_descriptor_change;

// With the default margin SIFT returns every keypoint whose window fits the crop, each the whole
// frame's, with a descriptor that is the same feature by eq. 5.2's bound and still names its
// whole-frame one by the database's ratio test.
TEST(DetectAndComputeInBox, TheCropGivesSiftsWholeFrameFeatures) {
  const cv::Mat rgb = Frame();
  if (rgb.empty()) GTEST_SKIP() << "graf/graf1.png of the shared test data is absent";
  const Comparison c =
      OverBoxes(FeatureExtractor::kSift, rgb, ObjectAcquisitionOptions().extraction_margin);
  EXPECT_GT(c.inside, 300);  // the boxes hold texture
  EXPECT_EQ(c.missing, 0);
  EXPECT_EQ(c.same, c.returned);
  EXPECT_EQ(c.matched, c.same);
  EXPECT_LT(c.worst, kSameFeature);
  EXPECT_EQ(c.outside, 0);
}

// M-SURF gets the whole frame whatever the margin: the same keypoints and descriptors.
TEST(DetectAndComputeInBox, MSurfIgnoresTheMargin) {
  const cv::Mat rgb = Frame();
  if (rgb.empty()) GTEST_SKIP() << "graf/graf1.png of the shared test data is absent";
  const Comparison c = OverBoxes(FeatureExtractor::kMSurf, rgb, 0);
  EXPECT_GT(c.returned, 300);
  EXPECT_EQ(c.same, c.returned);
  EXPECT_EQ(c.missing, 0);
  EXPECT_EQ(c.worst, 0.0);
}

// AKAZE's contrast factor is a percentile of the gradients of its whole input, so a crop shifts
// its scale space: not every keypoint survives, but those that do are the same features.
TEST(DetectAndComputeInBox, AkazeKeypointsFoundInTheCropAreTheWholeFramesFeatures) {
  const cv::Mat rgb = Frame();
  if (rgb.empty()) GTEST_SKIP() << "graf/graf1.png of the shared test data is absent";
  const Comparison c =
      OverBoxes(FeatureExtractor::kAkaze, rgb, ObjectAcquisitionOptions().extraction_margin);
  EXPECT_LT(c.missing, c.inside / 2);
  EXPECT_EQ(c.matched, c.same);
  EXPECT_LT(c.worst, kSameFeature);
  EXPECT_EQ(c.outside, 0);
}

// SIFT's pyramid halves per octave; with the crop's corner on an 8 px grid, a keypoint whose
// window and blur lie in the crop is computed from the same pixels as on the whole frame: the
// same descriptor up to float rounding. Without the grid (as at an odd corner) the octaves below
// the first sample other pixels.
TEST(DetectAndComputeInBox, SiftKeypointsClearOfTheCropsEdgeHaveTheWholeFramesDescriptors) {
  const cv::Mat rgb = Frame();
  if (rgb.empty()) GTEST_SKIP() << "graf/graf1.png of the shared test data is absent";
  for (int margin : {ObjectAcquisitionOptions().extraction_margin, 64}) {
    const Comparison c = OverBoxes(FeatureExtractor::kSift, rgb, margin);
    EXPECT_GT(c.clear, 300) << margin;
    EXPECT_LT(c.worst_clear, 1e-4) << margin;
  }
}

// A box at the frame's corner: the crop is clipped to the frame, and what it finds is in the box.
TEST(DetectAndComputeInBox, ABoxAtTheCornerIsClippedToTheFrame) {
  // Blobs of every size, so that each extractor finds keypoints in a corner box.
  cv::Mat rgb(240, 320, CV_8UC3, cv::Scalar::all(128));
  cv::RNG rng(4);
  for (int i = 0; i < 300; ++i)
    cv::circle(rgb, {rng.uniform(0, 320), rng.uniform(0, 240)}, rng.uniform(2, 12),
               cv::Scalar::all(rng.uniform(0, 255)), cv::FILLED);
  cv::GaussianBlur(rgb, rgb, {0, 0}, 1.0);
  for (FeatureExtractor e :
       {FeatureExtractor::kSift, FeatureExtractor::kMSurf, FeatureExtractor::kAkaze}) {
    const cv::Ptr<cv::Feature2D> f = CreateFeatureExtractor(e);
    for (const cv::Rect& box : {cv::Rect(0, 0, 96, 80), cv::Rect(224, 160, 96, 80)}) {
      std::vector<cv::KeyPoint> k;
      cv::Mat d;
      DetectAndComputeInBox(e, *f, rgb, box, 32, k, d);
      EXPECT_FALSE(k.empty()) << FeatureExtractorName(e);
      EXPECT_EQ(d.rows, int(k.size()));
      for (const cv::KeyPoint& p : k) EXPECT_TRUE(box.contains(cv::Point(p.pt))) << p.pt;
    }
  }
}

TEST(DetectAndComputeInBox, BadInputIsAClearError) {
  const cv::Mat rgb(240, 320, CV_8UC3, cv::Scalar::all(100));
  const cv::Ptr<cv::Feature2D> f = CreateFeatureExtractor(FeatureExtractor::kSift);
  std::vector<cv::KeyPoint> k;
  cv::Mat d;
  const auto message = [&](const cv::Mat& image, const cv::Rect& box) {
    try {
      DetectAndComputeInBox(FeatureExtractor::kSift, *f, image, box, 32, k, d);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(rgb, {300, 200, 96, 80}).find("not inside the 320x240"), std::string::npos);
  EXPECT_NE(message(rgb, {-1, 0, 10, 10}).find("not inside"), std::string::npos);
  EXPECT_NE(message(rgb, {10, 10, 0, 10}).find("empty"), std::string::npos);
  EXPECT_NE(message(cv::Mat(240, 320, CV_8UC1), {0, 0, 10, 10}).find("CV_8UC3"), std::string::npos);
  EXPECT_THROW(DetectAndComputeInBox(FeatureExtractor(7), *f, rgb, {0, 0, 10, 10}, 32, k, d),
               std::invalid_argument);
}

}  // namespace
}  // namespace novelty::objects
