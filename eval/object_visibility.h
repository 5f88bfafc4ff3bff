// Which objects a frame shows, from the simulator's ground truth (ids and novelty images,
// sim/output/ground_truth_writer.h): the positives of the recognition ROC (thesis fig. 5.5 b) and
// the true boxes the focus of attention is compared with (fig. 5.3 a, b).
#pragma once

#include <opencv2/core.hpp>

namespace novelty::eval {

/// Pixels of object `id` in `ids` (CV_32S).
int VisiblePixels(const cv::Mat& ids, int id);

struct NewObjectView {
  int id = -1;         ///< the added object seen most; −1 if none
  int pixels = 0;      ///< its pixels
  cv::Rect box;        ///< their bounding box
  int arm_pixels = 0;  ///< the person's arm in view (the object may be moving)
};

/// The added object (novelty == `added_code`, id ≠ `arm_id`) of most pixels in the frame.
/// `ids` CV_32S, `novelty` CV_8U of the same size; throws std::invalid_argument otherwise.
NewObjectView NewObjectInView(const cv::Mat& ids, const cv::Mat& novelty, int arm_id,
                              int added_code);

}  // namespace novelty::eval
