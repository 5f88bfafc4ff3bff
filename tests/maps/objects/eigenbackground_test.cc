// The eigenbackground on a background that varies with the light: seven images of a textured
// wall under gains and offsets; a new image under a light none of them had is explained by the
// eigenvectors, a square put in front of the wall is not.
#include "maps/objects/eigenbackground.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace novelty::objects {
namespace {

cv::Mat Wall() {
  cv::Mat w(120, 160, CV_32F);
  cv::RNG(5).fill(w, cv::RNG::UNIFORM, 0.0, 255.0);
  cv::GaussianBlur(w, w, cv::Size(0, 0), 3.0);
  cv::normalize(w, w, 40, 200, cv::NORM_MINMAX);
  return w;
}

cv::Mat Lit(const cv::Mat& wall, double gain, double offset, int seed) {
  cv::Mat noise(wall.size(), CV_32F), out;
  cv::RNG(seed).fill(noise, cv::RNG::NORMAL, 0.0, 2.0);
  out = wall * gain + offset + noise;
  return out;
}

double IoU(const cv::Mat& a, const cv::Mat& b) {
  return double(cv::countNonZero(a & b)) / std::max(1, cv::countNonZero(a | b));
}

TEST(Eigenbackground, ExplainsTheLightAndFindsWhatStandsInFront) {
  const cv::Mat wall = Wall();
  std::vector<cv::Mat> backgrounds;
  const double gains[] = {0.6, 0.8, 1.0, 1.2, 0.7, 1.1, 0.9},
               offsets[] = {10, -5, 0, 8, 20, -10, 3};
  for (int i = 0; i < 7; ++i) backgrounds.push_back(Lit(wall, gains[i], offsets[i], i));
  // A light between the known ones: no foreground (plain differencing with the mean would see it).
  const cv::Mat relit = Lit(wall, 1.15, -8, 11);
  EXPECT_EQ(cv::countNonZero(EigenbackgroundForeground(backgrounds, relit)), 0);
  cv::Mat mean = cv::Mat::zeros(wall.size(), CV_32F);
  for (const cv::Mat& b : backgrounds) mean += b / 7.0;
  EXPECT_GT(cv::countNonZero(cv::abs(relit - mean) > 25.0), 1000) << "the light alone is a change";
  // A dark square in front (the wall is 40 or brighter under every light): found, as the
  // largest region.
  cv::Mat with_square = relit.clone();
  const cv::Rect square(60, 40, 30, 30);
  cv::Mat truth = cv::Mat::zeros(wall.size(), CV_8UC1);
  truth(square).setTo(255);
  with_square(square).setTo(5.0f);
  const cv::Mat found = LargestRegion(EigenbackgroundForeground(backgrounds, with_square));
  EXPECT_GT(IoU(found, truth), 0.7);
}

TEST(Eigenbackground, UncoveredPixelsAreNeverForegroundAndBadInputIsRejected) {
  const cv::Mat wall = Wall();
  std::vector<cv::Mat> backgrounds = {Lit(wall, 1.0, 0, 1), Lit(wall, 0.8, 5, 2),
                                      Lit(wall, 1.1, 0, 3)};
  backgrounds[1](cv::Rect(0, 0, 40, 120)).setTo(std::nan(""));
  cv::Mat image = Lit(wall, 1.0, 0, 4);
  image(cv::Rect(0, 0, 80, 120)).setTo(255.0f);  // bright, half of it where a view had nothing
  const cv::Mat f = EigenbackgroundForeground(backgrounds, image);
  EXPECT_EQ(cv::countNonZero(f(cv::Rect(0, 0, 40, 120))), 0);
  EXPECT_GT(cv::countNonZero(f(cv::Rect(40, 0, 40, 120))), 40 * 120 * 8 / 10);
  EXPECT_THROW(EigenbackgroundForeground({wall}, image), std::invalid_argument);
  EXPECT_THROW(EigenbackgroundForeground(backgrounds, cv::Mat(10, 10, CV_32F)),
               std::invalid_argument);
  EigenbackgroundOptions o;
  o.components = 0;
  EXPECT_THROW(EigenbackgroundForeground(backgrounds, image, o), std::invalid_argument);
  EXPECT_EQ(cv::countNonZero(LargestRegion(cv::Mat::zeros(5, 5, CV_8UC1))), 0);
}

}  // namespace
}  // namespace novelty::objects
