#include "eval/cdnet_panel.h"

#include <stdexcept>

#include "eval/cdnet_scores.h"
#include "eval/side_by_side.h"

namespace novelty::eval {

namespace {

const cv::Vec3b kHit{255, 255, 255}, kFalseAlarm{230, 40, 40}, kMiss{40, 90, 255},
    kShadowAlarm{190, 60, 220}, kShadow{110, 50, 130}, kIgnored{60, 60, 60}, kNone{0, 0, 0};

}  // namespace

cv::Mat CdnetMaskImage(const cv::Mat& mask, const cv::Mat& truth, const cv::Mat& roi) {
  if (mask.type() != CV_8UC1 || (!truth.empty() && truth.size() != mask.size()) ||
      (!roi.empty() && roi.size() != mask.size()))
    throw std::invalid_argument("CdnetMaskImage: a CV_8UC1 mask, truth and ROI of its size");
  cv::Mat out(mask.size(), CV_8UC3);
  for (int r = 0; r < mask.rows; ++r)
    for (int c = 0; c < mask.cols; ++c) {
      const bool on = mask.at<std::uint8_t>(r, c) != 0;
      cv::Vec3b& o = out.at<cv::Vec3b>(r, c);
      if (truth.empty()) {
        o = on ? kHit : kNone;
        continue;
      }
      const int t = truth.at<std::uint8_t>(r, c);
      if ((!roi.empty() && roi.at<std::uint8_t>(r, c) == 0) || t == kCdnetUnknown ||
          t == kCdnetOutsideRoi)
        o = kIgnored;
      else if (t == kCdnetMotion)
        o = on ? kHit : kMiss;
      else if (on)
        o = t == kCdnetShadow ? kShadowAlarm : kFalseAlarm;
      else
        o = kNone;
    }
  return out;
}

cv::Mat CdnetTruthImage(const cv::Mat& truth) {
  cv::Mat out(truth.size(), CV_8UC3, cv::Scalar(0, 0, 0));
  out.setTo(cv::Scalar(kHit), truth == kCdnetMotion);
  out.setTo(cv::Scalar(kShadow), truth == kCdnetShadow);
  out.setTo(cv::Scalar(kIgnored), (truth == kCdnetUnknown) | (truth == kCdnetOutsideRoi));
  return out;
}

cv::Mat CdnetPanel(const cv::Mat& rgb, const cv::Mat& truth, const cv::Mat& roi,
                   const std::vector<cv::Mat>& masks, const std::vector<std::string>& names,
                   const std::string& label) {
  std::vector<cv::Mat> tiles = {rgb};
  std::vector<std::string> captions = {"camera " + label};
  if (!truth.empty()) {
    tiles.push_back(CdnetTruthImage(truth));
    captions.push_back("truth");
  }
  for (std::size_t k = 0; k < masks.size(); ++k) {
    tiles.push_back(CdnetMaskImage(masks[k], truth, roi));
    captions.push_back(names[k]);
  }
  return SideBySide(tiles, 4, captions);
}

}  // namespace novelty::eval
