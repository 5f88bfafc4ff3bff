// Why recognition in a whole frame misses an object it shows (thesis 5.2, fig. 5.5): eq. 5.4's
// matching of the object's learnt features repeated among only the frame's keypoints that lie on
// the object (simulator ground truth), so that nothing else in the frame can take the ratio
// test's second place. Matched here but not in the whole frame: the room's clutter lost the
// match. Missed here too: the object's own descriptors are not the learnt ones (viewpoint,
// light), and no change to the ratio test can find it.
#pragma once

#include <limits>
#include <opencv2/core.hpp>

#include "maps/objects/feature_database.h"
#include "maps/objects/object_recognition.h"

namespace novelty::eval {

struct MatchesOnObject {
  int keypoints = 0;  ///< the frame's keypoints on the object
  int matches = 0;    ///< N_k among those keypoints alone (eq. 5.4's ratio test)
  /// Mean over the object's database features of the descriptor distance to the nearest
  /// keypoint on the object; NaN without features or keypoints (and where not computed).
  double mean_nearest_distance = std::numeric_limits<double>::quiet_NaN();
};

/// `on_object` CV_8U, the frame's size, nonzero where the object is seen; a keypoint within
/// about `margin_px` of such a pixel (the mask dilated by an ellipse of that radius, keypoints
/// rounded to a pixel) counts as on it: a blob centred just outside the outline still describes
/// the object. `ratio`: the ratio test's bound (0.65 in the thesis); as in the whole frame, a
/// single keypoint on the object cannot pass it. Throws
/// std::invalid_argument for a bad mask, `object` not in `database`, margin_px < 0, or
/// descriptors of another width than the database's.
MatchesOnObject MatchOnObject(const objects::FeatureDatabase& database, int object,
                              const objects::FrameFeatures& frame, const cv::Mat& on_object,
                              int margin_px, double ratio);

}  // namespace novelty::eval
