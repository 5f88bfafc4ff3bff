#include "maps/objects/change_kind.h"

#include <gtest/gtest.h>

#include <limits>

namespace novelty::objects {
namespace {

// A table at 1.5 m; the region a 40 × 30 patch of it.
struct KindScene {
  cv::Mat region = cv::Mat::zeros(120, 160, CV_8U);
  cv::Mat predicted = cv::Mat(120, 160, CV_32F, cv::Scalar(1.5f));
  KindScene() { region(cv::Rect(50, 40, 40, 30)).setTo(255); }
};

TEST(ChangeKind, NearerIsAddedFartherIsRemoved) {
  KindScene s;
  cv::Mat observed = s.predicted.clone();
  observed(cv::Rect(50, 40, 40, 30)).setTo(1.38f);  // a cup 12 cm tall on the table: 8 % nearer
  ChangeClassification c = ClassifyChange(s.region, observed, s.predicted);
  EXPECT_EQ(c.kind, ChangeKind::kAdded);
  EXPECT_NEAR(c.observed_depth, 1.38, 1e-6);
  EXPECT_NEAR(c.predicted_depth, 1.5, 1e-6);
  // Taken away: the map predicts the cup (1.38 m) and the frame sees the table behind it.
  c = ClassifyChange(s.region, s.predicted, observed);
  EXPECT_EQ(c.kind, ChangeKind::kRemoved);
  // A change of colour only (a lamp, a sheet of paper): same depth.
  cv::Mat same = s.predicted.clone();
  same(cv::Rect(50, 40, 40, 30)).setTo(1.49f);
  EXPECT_EQ(ClassifyChange(s.region, same, s.predicted).kind, ChangeKind::kUnchanged);
}

TEST(ChangeKind, UnknownDepthsCountOnlyWhereBothAreKnown) {
  KindScene s;
  cv::Mat observed = s.predicted.clone();
  observed(cv::Rect(50, 40, 40, 30)).setTo(1.3f);
  observed(cv::Rect(50, 40, 40, 20)).setTo(std::numeric_limits<float>::quiet_NaN());  // 2/3 unknown
  ChangeClassification c = ClassifyChange(s.region, observed, s.predicted);
  EXPECT_NEAR(c.known_share, 1.0 / 3.0, 1e-9);
  EXPECT_EQ(c.kind, ChangeKind::kUnknown) << "too little depth to tell";
  ChangeKindOptions o;
  o.min_known_share = 0.3;
  EXPECT_EQ(ClassifyChange(s.region, observed, s.predicted, o).kind, ChangeKind::kAdded);
  EXPECT_EQ(ClassifyChange(cv::Mat::zeros(120, 160, CV_8U), observed, s.predicted).kind,
            ChangeKind::kUnknown);
  EXPECT_THROW(ClassifyChange(s.region, observed, cv::Mat(10, 10, CV_32F)), std::invalid_argument);
}

// With the span of the map's views (nearest, farthest): the view the previous frame replaced
// already holds the new cup (nearest 1.38 m), the others the table (farthest 1.5 m). The cup is
// still added; once taken away, the views that saw it make the table behind it removed.
TEST(ChangeKind, WithTheViewsSpanAViewThatAlreadyTookTheChangeDoesNotHideIt) {
  KindScene s;
  cv::Mat cup = s.predicted.clone();
  cup(cv::Rect(50, 40, 40, 30)).setTo(1.38f);
  cv::Mat span;
  cv::merge(std::vector<cv::Mat>{cup, s.predicted}, span);
  ChangeClassification c = ClassifyChange(s.region, cup, span);
  EXPECT_EQ(c.kind, ChangeKind::kAdded);
  EXPECT_NEAR(c.predicted_depth, 1.5, 1e-6) << "the farthest surface";
  c = ClassifyChange(s.region, s.predicted, span);
  EXPECT_EQ(c.kind, ChangeKind::kRemoved);
  EXPECT_NEAR(c.predicted_depth, 1.38, 1e-6) << "the nearest surface";
  // Views that agree: the span is one depth and the single-plane answers hold.
  cv::Mat same;
  cv::merge(std::vector<cv::Mat>{s.predicted, s.predicted}, same);
  EXPECT_EQ(ClassifyChange(s.region, s.predicted, same).kind, ChangeKind::kUnchanged);
  EXPECT_EQ(ClassifyChange(s.region, cup, same).kind, ChangeKind::kAdded);
  EXPECT_THROW(ClassifyChange(s.region, cup, cv::Mat(120, 160, CV_32FC3)), std::invalid_argument);
}

// The mask marks exactly the pixels ClassifyChange counts nearer: with a span, nearer than the
// farthest surface by 5 %; unknown depths never. Its count over the region, divided by the
// known pixels there, is ClassifyChange's nearer_share.
TEST(ChangeKind, NearerMaskMarksThePixelsCountedNearer) {
  KindScene s;
  cv::Mat span(s.predicted.size(), CV_32FC2, cv::Scalar(1.2f, 1.5f));  // nearest, farthest
  cv::Mat observed = s.predicted.clone();
  observed(cv::Rect(50, 40, 20, 30)).setTo(1.40f);  // 6.7 % nearer than 1.5: nearer
  observed(cv::Rect(70, 40, 10, 30)).setTo(1.44f);  // 4 %: not
  observed(cv::Rect(80, 40, 10, 10)).setTo(0.0f);   // unknown
  observed(cv::Rect(0, 0, 10, 10)).setTo(1.0f);     // nearer, outside the region
  const cv::Mat mask = NearerMask(observed, span);
  ASSERT_EQ(mask.type(), CV_8UC1);
  EXPECT_EQ(cv::countNonZero(mask), 20 * 30 + 10 * 10);
  EXPECT_EQ(cv::countNonZero(mask(cv::Rect(50, 40, 20, 30))), 20 * 30);
  EXPECT_EQ(mask.at<uchar>(45, 75), 0);
  EXPECT_EQ(mask.at<uchar>(45, 85), 0);
  const ChangeClassification c = ClassifyChange(s.region, observed, span);
  const int known = 40 * 30 - 10 * 10;
  EXPECT_NEAR(c.nearer_share, double(cv::countNonZero(mask & s.region)) / known, 1e-12);
  // A single predicted depth is its own nearest and farthest.
  EXPECT_EQ(cv::countNonZero(NearerMask(observed, s.predicted) != mask), 0);
  EXPECT_THROW(NearerMask(observed, cv::Mat(120, 160, CV_32FC3)), std::invalid_argument);
  EXPECT_THROW(NearerMask(observed, cv::Mat(10, 10, CV_32F)), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::objects
