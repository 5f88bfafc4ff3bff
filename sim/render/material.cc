#include "sim/render/material.h"

#include <cmath>

namespace novelty::sim {

namespace {

Eigen::Vector3f ImageLookup(const cv::Mat& image, const Eigen::Vector2f& uv) {
  // Tiled, bilinear, v = 0 at the image's bottom row so that text reads upright on +z faces.
  const float u = uv.x() - std::floor(uv.x()), v = uv.y() - std::floor(uv.y());
  const float x = u * float(image.cols - 1), y = (1.0f - v) * float(image.rows - 1);
  const int x0 = int(x), y0 = int(y);
  const int x1 = std::min(x0 + 1, image.cols - 1), y1 = std::min(y0 + 1, image.rows - 1);
  const float fx = x - float(x0), fy = y - float(y0);
  // An explicit return type: deduced, it would be an expression referring to a dead temporary.
  auto px = [&](int yy, int xx) -> Eigen::Vector3f {
    const cv::Vec3b c = image.at<cv::Vec3b>(yy, xx);
    return Eigen::Vector3f(c[0], c[1], c[2]) / 255.0f;
  };
  return (1 - fy) * ((1 - fx) * px(y0, x0) + fx * px(y0, x1)) +
         fy * ((1 - fx) * px(y1, x0) + fx * px(y1, x1));
}

}  // namespace

Eigen::Vector3f Material::DiffuseAt(const Eigen::Vector2f& uv) const {
  switch (texture.kind) {
    case Texture::Kind::kNone:
      return diffuse;
    case Texture::Kind::kChecker: {
      const int cu = int(std::floor(uv.x() * texture.cells));
      const int cv = int(std::floor(uv.y() * texture.cells));
      return ((cu + cv) & 1) ? texture.second : diffuse;
    }
    case Texture::Kind::kStripes:
      return (int(std::floor(uv.x() * texture.cells)) & 1) ? texture.second : diffuse;
    case Texture::Kind::kImage:
      return texture.image.empty() || !uv.allFinite() ? diffuse : ImageLookup(texture.image, uv);
  }
  return diffuse;
}

}  // namespace novelty::sim
