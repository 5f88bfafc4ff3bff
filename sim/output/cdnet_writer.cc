#include "sim/output/cdnet_writer.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "core/cdnet_labels.h"
#include "core/frame_stem.h"
#include "core/write_rgb_image.h"

namespace novelty::sim {

namespace fs = std::filesystem;

namespace {

cv::Mat Luminance(const cv::Mat& rgb) {
  cv::Mat y;
  cv::cvtColor(rgb, y, cv::COLOR_RGB2GRAY);
  y.convertTo(y, CV_32F);
  return y;
}

}  // namespace

cv::Mat CdnetTruth(const cv::Mat& ids, const std::vector<int>& foreground_ids, const cv::Mat& rgb,
                   const cv::Mat& background_rgb, const CdnetTruthOptions& o) {
  if (ids.type() != CV_32SC1 || rgb.type() != CV_8UC3 || background_rgb.type() != CV_8UC3 ||
      rgb.size() != ids.size() || background_rgb.size() != ids.size())
    throw std::invalid_argument("CdnetTruth: ids CV_32SC1, rgb and background CV_8UC3, one size");
  cv::Mat motion(ids.size(), CV_8UC1, cv::Scalar(0));
  for (int r = 0; r < ids.rows; ++r)
    for (int c = 0; c < ids.cols; ++c)
      if (std::find(foreground_ids.begin(), foreground_ids.end(), ids.at<int>(r, c)) !=
          foreground_ids.end())
        motion.at<std::uint8_t>(r, c) = 255;
  const cv::Mat y = Luminance(rgb), y0 = Luminance(background_rgb);
  const cv::Mat darker = (y0 - y > o.shadow_levels) & (y < (1 - o.shadow_darkening) * y0);
  cv::Mat truth(ids.size(), CV_8UC1, cv::Scalar(core::kCdnetStatic));
  truth.setTo(core::kCdnetShadow, darker);
  if (o.unknown_border > 0) {
    cv::Mat ring;
    const int k = 2 * o.unknown_border + 1;
    cv::dilate(motion, ring, cv::getStructuringElement(cv::MORPH_RECT, {k, k}));
    truth.setTo(core::kCdnetUnknown, ring);
  }
  truth.setTo(core::kCdnetMotion, motion);
  return truth;
}

CdnetWriter::CdnetWriter(const std::string& dir, int first_scored, int last_scored) : dir_(dir) {
  fs::create_directories(fs::path(dir) / "input");
  fs::create_directories(fs::path(dir) / "groundtruth");
  const std::string roi = (fs::path(dir) / "temporalROI.txt").string();
  std::ofstream out(roi);
  out << first_scored << ' ' << last_scored << '\n';
  if (!out) throw std::runtime_error(roi + ": cannot be written");
}

void CdnetWriter::WriteFrame(int frame, const cv::Mat& rgb, const cv::Mat& truth) {
  core::WriteRgbImage(dir_ + "/input/in" + core::FrameStem(frame) + ".jpg", rgb,
                      {cv::IMWRITE_JPEG_QUALITY, 95});
  core::WriteImage(dir_ + "/groundtruth/gt" + core::FrameStem(frame) + ".png", truth);
  if (!roi_written_) {
    core::WriteImage((fs::path(dir_) / "ROI.bmp").string(),
                     cv::Mat(rgb.size(), CV_8UC1, cv::Scalar(255)));
    roi_written_ = true;
  }
}

}  // namespace novelty::sim
