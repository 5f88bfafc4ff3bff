// Test helper: a random, smoothly varying texture standing in for a textured surface — uniform
// noise in [0, 255) blurred by a Gaussian of `sigma` pixels, then stretched to [lo, hi] when
// hi > lo (left as blurred otherwise). Shared by the stereo and localization tests.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace novelty::sensors {

inline cv::Mat BlurredNoise(cv::Size size, int type, std::uint64_t seed, double sigma,
                            double lo = 0, double hi = 0) {
  cv::Mat noise(size, type);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 255);
  cv::GaussianBlur(noise, noise, cv::Size(0, 0), sigma);
  if (hi > lo) cv::normalize(noise, noise, lo, hi, cv::NORM_MINMAX);
  return noise;
}

}  // namespace novelty::sensors
