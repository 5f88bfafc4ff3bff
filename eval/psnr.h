// Peak signal-to-noise ratio over a mask: the measure of view-synthesis quality (3.4).
#pragma once

#include <opencv2/core.hpp>

namespace novelty::eval {

/// 10 log10(peak² / MSE), the MSE taken over all channels of the pixels where `mask` is non-zero
/// (CV_8UC1; empty = all pixels). Returns +infinity for identical images and NaN for an empty
/// mask. Throws std::invalid_argument if sizes or channel counts differ.
double Psnr(const cv::Mat& a, const cv::Mat& b, const cv::Mat& mask = cv::Mat(),
            double peak = 255.0);

}  // namespace novelty::eval
