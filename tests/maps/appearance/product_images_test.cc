#include "maps/appearance/product_images.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/false_color.h"

namespace novelty::appearance {
namespace {

// Each picture is the false colour of its product on its documented scale.
TEST(ProductImages, DrawOnTheDocumentedScales) {
  AppearanceProducts p;
  p.surprise = cv::Mat(2, 3, CV_32FC1, cv::Scalar(5.0f));
  p.surprise.at<float>(0, 0) = std::nanf("");
  p.uncertainty = cv::Mat(2, 3, CV_32FC1, cv::Scalar(99.0f));
  DifferencingProducts d;
  d.difference = cv::Mat(2, 3, CV_32FC1, cv::Scalar(75.0f));
  const auto same = [](const cv::Mat& a, const cv::Mat& b) {
    return a.size() == b.size() && cv::norm(a, b, cv::NORM_INF) == 0.0;
  };
  EXPECT_TRUE(same(SurpriseImage(p), core::FalseColor(p.surprise, 20.0)));
  EXPECT_TRUE(same(UncertaintyImage(p), core::FalseColor(p.uncertainty, 1e4, true)));
  EXPECT_TRUE(same(DifferenceImage(d), core::FalseColor(d.difference, 150.0)));
  // 5 nats of 20 and 75 of 150 are a quarter and half way up the colour map: different colours.
  EXPECT_NE(SurpriseImage(p).at<cv::Vec3b>(1, 1), DifferenceImage(d).at<cv::Vec3b>(1, 1));
  EXPECT_EQ(SurpriseImage(p).at<cv::Vec3b>(0, 0), cv::Vec3b(60, 60, 60));  // no prediction
  EXPECT_TRUE(SurpriseImage(AppearanceProducts()).empty());
  EXPECT_EQ(SurpriseCaption(), "surprise (0-20)");
  EXPECT_EQ(UncertaintyCaption(), "uncertainty (log, 0-10000)");
}

}  // namespace
}  // namespace novelty::appearance
