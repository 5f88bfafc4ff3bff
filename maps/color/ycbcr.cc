#include "maps/color/ycbcr.h"

#include <stdexcept>
#include <string>

namespace novelty::color {

namespace {

cv::Vec3f Apply(const cv::Matx34d& m, const cv::Vec3f& v) {
  cv::Vec3f out;
  for (int r = 0; r < 3; ++r) {
    out[r] = static_cast<float>(m(r, 0) * v[0] + m(r, 1) * v[1] + m(r, 2) * v[2] + m(r, 3));
  }
  return out;
}

// Into `out` (reusing its buffer): the image as float, then in place OpenCV's vectorised
// per-pixel affine map (each output pixel depends on its own input pixel only).
void Apply(const cv::Mat& in, const cv::Matx34d& m, cv::Mat& out) {
  in.convertTo(out, CV_32F);
  cv::transform(out, out, cv::Matx34f(m));
}

}  // namespace

// clang-format off
cv::Matx34d RgbToYCbCrMatrix() {
  const double kr = kLumaRed, kg = kLumaGreen, kb = kLumaBlue;
  const double sb = 0.5 / (1.0 - kb), sr = 0.5 / (1.0 - kr);
  return {kr,              kg,       kb,              0.0,
          -sb * kr,        -sb * kg, sb * (1.0 - kb), kChromaOffset,
          sr * (1.0 - kr), -sr * kg, -sr * kb,        kChromaOffset};
}

cv::Matx34d YCbCrToRgbMatrix() {
  // R = Y + 2(1-Kr)·Cr', B = Y + 2(1-Kb)·Cb', G = (Y - Kr R - Kb B) / Kg, with Cx' = Cx - offset.
  const double kr = kLumaRed, kg = kLumaGreen, kb = kLumaBlue, o = kChromaOffset;
  const double r_cr = 2.0 * (1.0 - kr), b_cb = 2.0 * (1.0 - kb);
  const double g_cb = -kb * b_cb / kg, g_cr = -kr * r_cr / kg;
  return {1.0, 0.0,  r_cr, -r_cr * o,
          1.0, g_cb, g_cr, -(g_cb + g_cr) * o,
          1.0, b_cb, 0.0,  -b_cb * o};
}
// clang-format on

cv::Vec3f RgbToYCbCr(const cv::Vec3f& rgb) {
  return Apply(RgbToYCbCrMatrix(), rgb);
}
cv::Vec3f YCbCrToRgb(const cv::Vec3f& ycbcr) {
  return Apply(YCbCrToRgbMatrix(), ycbcr);
}

void RgbToYCbCr(const cv::Mat& rgb, cv::Mat& ycbcr) {
  if (rgb.type() != CV_8UC3 && rgb.type() != CV_32FC3) {
    throw std::invalid_argument(
        "RgbToYCbCr: expected an RGB image of type CV_8UC3 or CV_32FC3, "
        "got OpenCV type " +
        std::to_string(rgb.type()));
  }
  Apply(rgb, RgbToYCbCrMatrix(), ycbcr);
}

void YCbCrToRgb(const cv::Mat& ycbcr, cv::Mat& rgb) {
  if (ycbcr.type() != CV_32FC3) {
    throw std::invalid_argument(
        "YCbCrToRgb: expected a YCbCr image of type CV_32FC3, got OpenCV "
        "type " +
        std::to_string(ycbcr.type()));
  }
  Apply(ycbcr, YCbCrToRgbMatrix(), rgb);
}

cv::Mat RgbToYCbCr(const cv::Mat& rgb) {
  cv::Mat ycbcr;
  RgbToYCbCr(rgb, ycbcr);
  return ycbcr;
}

cv::Mat YCbCrToRgb(const cv::Mat& ycbcr) {
  cv::Mat rgb;
  YCbCrToRgb(ycbcr, rgb);
  return rgb;
}

}  // namespace novelty::color
