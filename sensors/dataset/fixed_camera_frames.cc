#include "sensors/dataset/fixed_camera_frames.h"

#include <filesystem>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <stdexcept>

#include "sensors/dataset/fixed_camera_folder.h"
#include "sensors/dataset/lighting_folder_reader.h"

namespace novelty::sensors {

namespace fs = std::filesystem;

namespace {

std::string SizeText(const cv::Size& s) {
  return std::to_string(s.width) + "x" + std::to_string(s.height);
}

// A plain folder's images as a CDnet folder without ground truth: numbered 1, 2, … in name order.
CdnetFolder PlainFolder(const std::string& dir) {
  const ImageFolderListing listing = ListImageFolder(dir);
  if (listing.images.empty()) throw std::runtime_error(dir + ": no image in the folder");
  CdnetFolder f;
  f.dir = dir;
  f.inputs = listing.images;
  for (std::size_t k = 0; k < f.inputs.size(); ++k) f.numbers.push_back(int(k) + 1);
  f.truths.assign(f.inputs.size(), "");
  if (!listing.mask.empty()) f.roi = ReadFolderMask(listing.mask);
  return f;
}

}  // namespace

FixedCameraFrames::FixedCameraFrames(const std::string& path, long long max_pixels)
    : path_(path), max_pixels_(max_pixels) {
  if (fs::is_directory(path)) {
    const bool cdnet = fs::is_directory(fs::path(path) / "input");
    kind_ = cdnet ? "CDnet folder" : "image folder";
    folder_ = cdnet ? ReadCdnetFolder(path) : PlainFolder(path);
    size_ = int(folder_.inputs.size());
    return;
  }
  if (!fs::is_regular_file(path))
    throw std::runtime_error(path + ": no such folder of images, CDnet folder or video file");
  kind_ = "video";
  video_ = std::make_unique<cv::VideoCapture>(path, cv::CAP_FFMPEG);  // others print noise
  if (!video_->isOpened())
    throw std::runtime_error(path + ": OpenCV cannot open it as a video (nor is it a folder)");
  const cv::Size size(int(video_->get(cv::CAP_PROP_FRAME_WIDTH)),
                      int(video_->get(cv::CAP_PROP_FRAME_HEIGHT)));
  if (double(size.width) * size.height > double(max_pixels))
    throw std::runtime_error(path + ": frames of " + SizeText(size) + " are over " +
                             std::to_string(max_pixels) + " pixels");
  size_ = std::max(0, int(video_->get(cv::CAP_PROP_FRAME_COUNT)));
}

FixedCameraFrames::~FixedCameraFrames() = default;

bool FixedCameraFrames::Next(FixedCameraFrame& frame) {
  if (video_) {
    cv::Mat bgr;
    if (!video_->read(bgr) || bgr.empty()) return false;
    frame.number = ++next_;
    frame.source = path_ + " frame " + std::to_string(frame.number);
    if (bgr.type() != CV_8UC3) throw std::runtime_error(frame.source + ": not 8-bit colour");
    cv::cvtColor(bgr, frame.rgb, cv::COLOR_BGR2RGB);
    frame.truth.clear();
  } else {
    if (next_ >= int(folder_.inputs.size())) return false;
    const std::size_t k = std::size_t(next_++);
    frame.number = folder_.numbers[k];
    frame.source = folder_.inputs[k];
    frame.rgb = ReadImageRgb8(frame.source, max_pixels_);
    frame.truth = folder_.truths[k];
  }
  if (first_size_.empty()) first_size_ = frame.rgb.size();
  if (frame.rgb.size() != first_size_)
    throw std::runtime_error(frame.source + ": " + SizeText(frame.rgb.size()) +
                             ", the first frame " + SizeText(first_size_));
  if (!roi().empty() && roi().size() != first_size_)
    throw std::runtime_error(path_ + ": the region of interest is " + SizeText(roi().size()) +
                             ", the frames " + SizeText(first_size_));
  return true;
}

}  // namespace novelty::sensors
