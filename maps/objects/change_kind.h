// Added or removed (thesis 5.3 and its outlook): surprise says that a region changed, not how.
// An object put down is nearer to the camera than what the map predicts there; an object taken
// away leaves the farther background it hid. The region's observed mean depth against the mean
// depth the map predicts for the same pixels tells them apart — so that the learner learns the
// added object and never the background a removed one uncovers. Equal depths say that the
// region's shape did not change: a change of light or colour, or sensor noise — no object to
// learn (nor one as flat as a sheet of paper: its millimetres are below any depth sensor's noise).
#pragma once

#include <opencv2/core.hpp>

namespace novelty::objects {

enum class ChangeKind {
  kUnknown,    ///< too few pixels with both depths to tell
  kAdded,      ///< nearer than predicted
  kRemoved,    ///< farther than predicted
  kUnchanged,  ///< both depths known and within min_relative_difference of each other
};

struct ChangeKindOptions {
  /// The means must differ by at least this fraction of the predicted depth: 5 % is about three
  /// times the RGB-D sensor's depth noise at 1–2 m and above the stereo depth's typical 3 %.
  double min_relative_difference = 0.05;
  /// At least this share of the region's pixels must have both depths, else kUnknown.
  double min_known_share = 0.5;
  /// Added (removed) if at least this share of the pixels with both depths is nearer (farther)
  /// by min_relative_difference; the larger share decides if both are.
  double min_changed_share = 0.25;
};

struct ChangeClassification {
  ChangeKind kind = ChangeKind::kUnknown;
  double observed_depth = 0.0;   ///< mean over the pixels with both depths (m)
  /// Mean of the map's prediction there (m): of the nearest surface if removed, else of the
  /// farthest.
  double predicted_depth = 0.0;
  double known_share = 0.0;      ///< share of the region's pixels with both depths
  double nearer_share = 0.0;     ///< share of those nearer than predicted (the farthest view)
  double farther_share = 0.0;    ///< share of those farther than predicted (the nearest view)
};

/// `region`: CV_8U, non-zero where the change is (FocusOfAttention::region); the observed depth
/// CV_32F in metres, 0 or NaN unknown; the predicted depth CV_32F, or CV_32FC2 holding per pixel
/// the nearest and the farthest surface over the map's views (AppearanceProducts::
/// expected_depth_span). With the span, a region is added if nearer than the farthest surface a
/// view saw there, removed if farther than the nearest: a map that takes each frame into its
/// views (appearance_map.h) expects a new object from the next frame on in the view it just
/// replaced, while the views it has not replaced yet still show what was there before. Throws
/// std::invalid_argument for other types or sizes.
ChangeClassification ClassifyChange(const cv::Mat& region, const cv::Mat& observed_depth,
                                    const cv::Mat& predicted_depth,
                                    const ChangeKindOptions& options = {});

/// Pixel by pixel, where ClassifyChange counts a pixel nearer: CV_8U, 255 where the observed and
/// predicted depths are known and the observed is nearer than the farthest surface predicted
/// there by the factor (1 − min_relative_difference) — where something now stands in front of
/// a surface a view saw.
/// The same depths as ClassifyChange; throws std::invalid_argument for other types or sizes.
cv::Mat NearerMask(const cv::Mat& observed_depth, const cv::Mat& predicted_depth,
                   const ChangeKindOptions& options = {});

}  // namespace novelty::objects
