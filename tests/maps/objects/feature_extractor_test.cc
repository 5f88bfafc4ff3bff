#include "maps/objects/feature_extractor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "maps/objects/object_acquisition.h"

namespace novelty::objects {
namespace {

// graf1 (a real photograph) at 320×240 as R, G, B, or empty when the shared data is absent.
cv::Mat Frame() {
  const char* shared = std::getenv("NOVELTY_SHARED_DATA");
  const std::string path = std::string(shared ? shared : "") + "/graf/graf1.png";
  if (!shared || !std::filesystem::exists(path)) return {};
  cv::Mat img = cv::imread(path, cv::IMREAD_COLOR), out;
  cv::resize(img, out, {320, 240}, 0, 0, cv::INTER_AREA);
  cv::cvtColor(out, out, cv::COLOR_BGR2RGB);
  return out;
}

// The share of a keypoint's axis-aligned descriptor window (side window_per_size · size) that
// lies in `box`.
double WindowShareIn(const cv::KeyPoint& k, double window_per_size, const cv::Rect2d& box) {
  const double h = 0.5 * window_per_size * k.size;
  const cv::Rect2d w(k.pt.x - h, k.pt.y - h, 2 * h, 2 * h);
  return (w & box).area() / w.area();
}

// How the features `e` finds in `box` on a crop with `margin` compare with those it finds on the
// whole frame with the box as mask, over the whole-frame keypoints the object learner could select
// (window ≥ 80 % in the box, eq. 5.5's T with the box for the surprise).
struct Comparison {
  int learnable = 0;  // whole-frame keypoints in the box, window ≥ 80 % in it
  int same = 0;       // of them, found in the crop at the same place, size and angle
  int matched = 0;    // of those, whose crop descriptor finds its whole-frame one by the ratio test
  double worst = 0.0;  // the largest descriptor distance among the same, relative to its norm
  int outside = 0;     // crop keypoints whose centre is not in the box
};

Comparison Compare(FeatureExtractor e, const cv::Mat& rgb, const cv::Rect& box, int margin) {
  const cv::Ptr<cv::Feature2D> f = CreateFeatureExtractor(e);
  std::vector<cv::KeyPoint> whole, crop;
  cv::Mat dw, dc;
  DetectAndComputeInBox(*f, rgb, box, -1, whole, dw);
  DetectAndComputeInBox(*f, rgb, box, margin, crop, dc);
  Comparison c;
  for (const cv::KeyPoint& k : crop) c.outside += !box.contains(cv::Point(k.pt));
  for (std::size_t i = 0; i < whole.size(); ++i) {
    const cv::KeyPoint& a = whole[i];
    if (WindowShareIn(a, DescriptorWindowPerSize(e), box) < 0.8) continue;
    ++c.learnable;
    for (std::size_t j = 0; j < crop.size(); ++j) {
      const cv::KeyPoint& b = crop[j];
      if (cv::norm(a.pt - b.pt) > 1e-3 || std::abs(a.size - b.size) > 1e-3 * a.size ||
          std::abs(a.angle - b.angle) > 1e-2)
        continue;
      ++c.same;
      const double d = cv::norm(dw.row(int(i)), dc.row(int(j)));
      c.worst = std::max(c.worst, d / cv::norm(dw.row(int(i))));
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
      sum.learnable += c.learnable;
      sum.same += c.same;
      sum.matched += c.matched;
      sum.worst = std::max(sum.worst, c.worst);
      sum.outside += c.outside;
    }
  std::printf(
      "%s, margin %d: %d of %d learnable keypoints the same, %d matched, descriptors "
      "within %.4f of their norm\n",
      FeatureExtractorName(e).c_str(), margin, sum.same, sum.learnable, sum.matched, sum.worst);
  return sum;
}

// With the default margin SIFT and M-SURF find every keypoint the learner could select, and each
// crop descriptor still names its whole-frame feature by the database's ratio test.
TEST(DetectAndComputeInBox, TheDefaultMarginKeepsEveryLearnableKeypoint) {
  const cv::Mat rgb = Frame();
  if (rgb.empty()) GTEST_SKIP() << "graf/graf1.png of the shared test data is absent";
  const int margin = ObjectAcquisitionOptions().extraction_margin;
  for (FeatureExtractor e : {FeatureExtractor::kSift, FeatureExtractor::kMSurf}) {
    const Comparison c = OverBoxes(e, rgb, margin);
    EXPECT_GT(c.learnable, 300) << FeatureExtractorName(e);  // the boxes hold texture
    EXPECT_EQ(c.same, c.learnable) << FeatureExtractorName(e);
    EXPECT_EQ(c.matched, c.same) << FeatureExtractorName(e);
    EXPECT_EQ(c.outside, 0) << FeatureExtractorName(e);
  }
}

// AKAZE's contrast factor is a percentile of the gradients of its whole input, so a crop shifts
// its scale space: not every keypoint survives, but those that do are the same features.
TEST(DetectAndComputeInBox, AkazeKeypointsFoundInTheCropAreTheWholeFramesFeatures) {
  const cv::Mat rgb = Frame();
  if (rgb.empty()) GTEST_SKIP() << "graf/graf1.png of the shared test data is absent";
  const Comparison c =
      OverBoxes(FeatureExtractor::kAkaze, rgb, ObjectAcquisitionOptions().extraction_margin);
  EXPECT_GT(c.same, c.learnable / 2);
  EXPECT_EQ(c.matched, c.same);
  EXPECT_EQ(c.outside, 0);
}

// SIFT's pyramid halves per octave; with the crop's corner on an 8 px grid and a margin that
// holds every learnable keypoint's window and blur, the crop computes them from the same pixels:
// the same descriptors up to float rounding.
TEST(DetectAndComputeInBox, AWideMarginGivesSiftsWholeFrameDescriptors) {
  const cv::Mat rgb = Frame();
  if (rgb.empty()) GTEST_SKIP() << "graf/graf1.png of the shared test data is absent";
  const Comparison c = OverBoxes(FeatureExtractor::kSift, rgb, 64);
  EXPECT_EQ(c.same, c.learnable);
  EXPECT_LT(c.worst, 1e-4);
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
      DetectAndComputeInBox(*f, rgb, box, 32, k, d);
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
      DetectAndComputeInBox(*f, image, box, 32, k, d);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(rgb, {300, 200, 96, 80}).find("not inside the 320x240"), std::string::npos);
  EXPECT_NE(message(rgb, {-1, 0, 10, 10}).find("not inside"), std::string::npos);
  EXPECT_NE(message(rgb, {10, 10, 0, 10}).find("empty"), std::string::npos);
  EXPECT_NE(message(cv::Mat(240, 320, CV_8UC1), {0, 0, 10, 10}).find("CV_8UC3"), std::string::npos);
}

}  // namespace
}  // namespace novelty::objects
