// The frames of one fixed camera, one at a time, from what users have: a folder in CDnet's
// layout (cdnet_folder.h; its ground truth, ROI and temporal ROI come along), a plain folder of
// images (name order by lighting_folder_reader.h's rules, mask.png as the region of interest), or
// a video file OpenCV's videoio reads (FFmpeg: .mp4, .avi, .mkv, …; frames numbered from 1).
#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <string>

#include "sensors/dataset/cdnet_folder.h"
#include "sensors/dataset/image_header.h"

namespace cv {
class VideoCapture;
}

namespace novelty::sensors {

struct FixedCameraFrame {
  int number = 0;      ///< 1-based; a CDnet frame's from its file name
  std::string source;  ///< the file, or "VIDEO frame N", for messages
  cv::Mat rgb;         ///< CV_8UC3 R G B
  std::string truth;   ///< its ground truth's path, "" where none
};

class FixedCameraFrames {
 public:
  /// Opens `path`. Throws std::runtime_error naming it: a folder with no image, a CDnet folder
  /// ReadCdnetFolder refuses, a file OpenCV cannot open as a video, a video over `max_pixels`.
  explicit FixedCameraFrames(const std::string& path,
                             long long max_pixels = kDefaultMaxImagePixels);
  ~FixedCameraFrames();
  FixedCameraFrames(const FixedCameraFrames&) = delete;
  FixedCameraFrames& operator=(const FixedCameraFrames&) = delete;

  /// The next frame into `frame`; false after the last. Throws std::runtime_error naming a frame
  /// that cannot be read or is of another size than the first.
  bool Next(FixedCameraFrame& frame);

  /// "CDnet folder", "image folder" or "video".
  const std::string& kind() const { return kind_; }
  /// Frames in all (a video's as its container says; 0 where it does not).
  int size() const { return size_; }
  /// CV_8UC1, 255 where scored; empty: everywhere.
  const cv::Mat& roi() const { return folder_.roi; }
  /// Whether frame `number` lies in the temporal ROI (always, without one).
  bool scored(int number) const { return folder_.scored(number); }

 private:
  std::string path_, kind_;
  long long max_pixels_;
  CdnetFolder folder_;  // the folders' frames (a plain folder's numbered 1, 2, …)
  std::unique_ptr<cv::VideoCapture> video_;
  int size_ = 0, next_ = 0;
  cv::Size first_size_;
};

}  // namespace novelty::sensors
