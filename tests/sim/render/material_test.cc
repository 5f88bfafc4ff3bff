#include "sim/render/material.h"

#include <gtest/gtest.h>

#include <cmath>

namespace novelty::sim {
namespace {

// A 2×2 RGB image: the lookup at the centre is the mean of the four pixels, at a corner
// (v = 0 is the bottom row) that pixel exactly.
Material TwoByTwo() {
  Material m;
  m.texture.kind = Texture::Kind::kImage;
  m.texture.image = cv::Mat(2, 2, CV_8UC3);
  m.texture.image.at<cv::Vec3b>(0, 0) = {255, 0, 0};
  m.texture.image.at<cv::Vec3b>(0, 1) = {0, 255, 0};
  m.texture.image.at<cv::Vec3b>(1, 0) = {0, 0, 255};
  m.texture.image.at<cv::Vec3b>(1, 1) = {51, 102, 153};
  return m;
}

TEST(Material, ImageTextureIsBilinearInThePixels) {
  const Material m = TwoByTwo();
  const Eigen::Vector3f centre = m.DiffuseAt({0.5f, 0.5f});
  const Eigen::Vector3f mean = Eigen::Vector3f(306, 357, 408) / (4 * 255.0f);
  EXPECT_LT((centre - mean).norm(), 1e-5f) << centre.transpose();
  // Bottom-left corner (u = 0, v = 0) is image row 1, column 0.
  EXPECT_LT((m.DiffuseAt({0.0f, 0.0f}) - Eigen::Vector3f(0, 0, 1)).norm(), 1e-5f);
  // Tiled: u + 3, v − 2 is the same place.
  EXPECT_LT((m.DiffuseAt({3.25f, -1.75f}) - m.DiffuseAt({0.25f, 0.25f})).norm(), 1e-5f);
}

TEST(Material, ImageTextureAtNonFiniteCoordinatesIsTheDiffuseColourNotACrash) {
  Material m = TwoByTwo();
  m.diffuse = {0.2f, 0.3f, 0.4f};
  for (float bad : {std::nanf(""), INFINITY, -INFINITY}) {
    const Eigen::Vector3f c = m.DiffuseAt({bad, 0.5f});
    EXPECT_TRUE(c.allFinite()) << bad;
  }
}

}  // namespace
}  // namespace novelty::sim
