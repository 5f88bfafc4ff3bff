// A fixed camera's frames in the layout of the CDnet change-detection benchmark
// (changedetection.net; sensors/dataset/cdnet_folder.h reads it), written beside the rawlog:
//   DIR/input/in000001.jpg        the camera's frames (JPEG, quality 95)
//   DIR/groundtruth/gt000001.png  255 motion, 170 unknown, 50 shadow, 0 static
//   DIR/ROI.bmp                   255 everywhere: the whole view is scored
//   DIR/temporalROI.txt           "FIRST LAST": the frames scored; those before let a method
//                                 learn the background
// Ground truth per frame (CdnetTruth): motion is every pixel showing a foreground object (one
// added since the start, moved, or the person's arm); unknown a ring of `unknown_border` pixels
// outside it, where JPEG blurs the edge; shadow every other pixel that the foreground darkens —
// the frame against a render of its background under the same light, exposure and noise.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace novelty::sim {

struct CdnetTruthOptions {
  /// Shadow where the foreground darkens the background's luminance by more than this fraction…
  double shadow_darkening = 0.03;
  /// …and by at least this many 8-bit levels (sensor noise, identical in both renders, cancels;
  /// this keeps rounding out).
  double shadow_levels = 3.0;
  /// Pixels of the unknown ring outside motion regions.
  int unknown_border = 1;
};

/// Labels of one frame. ids CV_32SC1 (the render's object ids), rgb and background_rgb CV_8UC3
/// of the same size.
cv::Mat CdnetTruth(const cv::Mat& ids, const std::vector<int>& foreground_ids, const cv::Mat& rgb,
                   const cv::Mat& background_rgb, const CdnetTruthOptions& options = {});

class CdnetWriter {
 public:
  /// Creates DIR/input and DIR/groundtruth and writes temporalROI.txt (frames first…last).
  CdnetWriter(const std::string& dir, int first_scored, int last_scored);
  /// frame is 1-based; rgb CV_8UC3 R G B, truth CV_8UC1 labels. Writes ROI.bmp with the first.
  /// Throws std::runtime_error naming a file that cannot be written.
  void WriteFrame(int frame, const cv::Mat& rgb, const cv::Mat& truth);

 private:
  std::string dir_;
  bool roi_written_ = false;
};

}  // namespace novelty::sim
