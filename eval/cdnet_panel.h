// The picture of one frame of a foreground run: the camera image, the ground truth (if any) and
// each method's mask scored against it the CDnet way — white hits (motion found), red false
// alarms, blue misses, violet false alarms on shadow, the ignored pixels (unknown, outside the
// ROI) dark grey — so that where each method fails is seen, not only how often.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace novelty::eval {

/// A mask (CV_8UC1, non-zero foreground) as CV_8UC3: against `truth` (CDnet labels, CV_8UC1) and
/// `roi` (empty or CV_8UC1, 0 ignored) in the colours above, or white on black without truth.
cv::Mat CdnetMaskImage(const cv::Mat& mask, const cv::Mat& truth = {}, const cv::Mat& roi = {});

/// The ground truth as CV_8UC3: motion white, shadow violet, unknown dark grey, static black.
cv::Mat CdnetTruthImage(const cv::Mat& truth);

/// camera | truth | mask of each of `names`, captioned; `label` heads the camera's caption.
cv::Mat CdnetPanel(const cv::Mat& rgb, const cv::Mat& truth, const cv::Mat& roi,
                   const std::vector<cv::Mat>& masks, const std::vector<std::string>& names,
                   const std::string& label);

}  // namespace novelty::eval
