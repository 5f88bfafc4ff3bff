// A sequence in the layout of the CDnet change-detection benchmark (changedetection.net): a
// fixed camera's frames input/in000001.jpg …, optionally ground truth groundtruth/gt000001.png …
// (labels as eval/cdnet_scores.h reads them), ROI.bmp (non-zero = the region scored) and
// temporalROI.txt ("FIRST LAST": the frames scored, 1-based; the ones before let a method learn
// the background). Frames are numbered by their file names.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace novelty::sensors {

struct CdnetFolder {
  std::string dir;
  std::vector<int> numbers;                   ///< each frame's number (in000012.jpg: 12), ascending
  std::vector<std::string> inputs;            ///< the frames' paths
  std::vector<std::string> truths;            ///< per frame its ground truth's path, "" where none
  cv::Mat roi;                                ///< CV_8UC1 255 = scored; empty without ROI.bmp
  int temporal_first = 1, temporal_last = 0;  ///< frames scored (last 0: to the end)
  bool scored(int number) const {
    return number >= temporal_first && (temporal_last == 0 || number <= temporal_last);
  }
};

/// Lists `dir`; throws std::runtime_error naming the folder or file: no input/ folder, no frame
/// in it, a frame name that is not inNNNNNN, a temporalROI.txt that is not two frame numbers, a
/// ROI.bmp that cannot be read.
CdnetFolder ReadCdnetFolder(const std::string& dir);

/// A ground-truth image as CV_8UC1 labels; throws std::runtime_error naming it.
cv::Mat ReadCdnetTruth(const std::string& path);

}  // namespace novelty::sensors
