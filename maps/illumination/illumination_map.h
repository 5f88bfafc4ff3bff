// The illumination-invariant image-based map (thesis ch. 6) for a moving camera: M sequences of a
// static scene under different lighting, all posed in one frame (a tracker's, or registered by
// sensors/localization/sequence_registration.h, 6.1.1), become invariant images at a dense series
// of common viewpoints (6.1, fig. 6.1), each with its illumination statistics and shapes (6.2);
// a new frame is judged against them interpolated at its pose (6.3).
//
//  - Viewpoints: along the first lighting's path, a frame becomes a viewpoint when it is at least
//    `viewpoint_distance` or `viewpoint_angle_deg` from the last one ("similarly dense as the
//    spacing of the real camera views"); its depth map is the viewpoint's geometry.
//  - Acquisition: at each viewpoint a virtual image is synthesised from each lighting's frames
//    (ch. 3: view selection, depth-mesh warp, blend); the frames of a lighting are let go as soon
//    as its virtual images are made (when the next lighting begins, or at Build), so memory holds
//    one lighting's frames and the virtual images. The invariant image (invariant_image.h, with the
//    virtual images' coverage) and the model (illumination_model.h) follow at Build.
//  - Detection: the viewpoints are selected for the frame's pose like reference views (3.3.1);
//    their invariant images (with their coverage), and the shapes each lighting left, are warped
//    into the frame and averaged — the interpolation the thesis does for its appearance priors —
//    and the gamma parameters and T_Y are averaged with the same weights. Then 6.3 runs
//    (illumination_novelty.h) on the interpolated viewpoint.
// Memory: per viewpoint a float depth map, the invariant image and its coverage (4 floats a
// pixel) and one byte a pixel per lighting for the shapes: about 2.2 MB at 320×240 with 9
// lightings.
#pragma once

#include <Eigen/Geometry>
#include <limits>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/eigen_abi.h"
#include "core/frame.h"
#include "maps/illumination/illumination_model.h"
#include "maps/illumination/illumination_novelty.h"
#include "maps/illumination/invariant_image.h"
#include "maps/illumination/lighting_threshold.h"
#include "maps/illumination/zernike_moments.h"
#include "maps/views/reference_view_store.h"
#include "maps/views/view_selection.h"
#include "maps/views/view_synthesis.h"

namespace novelty::illumination {

/// Most lightings a map holds (a map file's shapes plane has a channel per lighting).
inline constexpr int kMaxLightings = 64;

/// Defaults: the thesis's values. CIlluminationInvariantMap's options, which users set, default to
/// the best measured setting instead (mrpt_plugins/illumination_invariant_map_options.h).
struct IlluminationMapOptions {
  /// A frame of the first lighting becomes a viewpoint when its camera is at least this far (m)
  /// from the last viewpoint's ...
  double viewpoint_distance = 0.05;
  /// ... or turned at least this much (degrees) from it.
  double viewpoint_angle_deg = 5.0;
  /// Which frames make a virtual image, and which viewpoints a new frame's interpolation (3.3.1).
  views::ViewSelectionOptions selection;
  /// The warp and blend of both (ch. 3 defaults).
  views::SynthesisOptions synthesis;
  /// A viewpoint is kept only if at least this share of the pixels its depth knows has an
  /// invariant value (covered by min_lightings virtual images): a viewpoint the lightings hardly
  /// saw is noise.
  double min_viewpoint_coverage = 0.5;
  InvariantImageOptions invariant;
  /// κ = 0.5: the Lambertian default (eq. 6.18).
  IlluminationModelOptions model;
  ZernikeOptions zernike;
  /// Its min_intensity is the invariant's (a frame is clipped as the images the map was made of).
  IlluminationNoveltyOptions novelty;
  /// The decision threshold on Δ learnt at Build from the training lightings alone.
  LightingThresholdOptions threshold;
};

/// What one viewpoint holds besides its geometry.
struct IlluminationViewpointModel {
  IlluminationModel model;  ///< gamma fits, widths, T_Y (its shapes live in the view's plane)
  double coverage = 0.0;    ///< share of pixels the invariant image covers
};

/// A frame judged against the map.
struct IlluminationMapResult {
  ViewpointIllumination viewpoint;  ///< interpolated at the frame's pose
  IlluminationNovelty novelty;      ///< 6.3 against it (empty when nothing covers the frame)
  std::vector<int> viewpoints;      ///< the viewpoints used
  double coverage = 0.0;            ///< share of the frame's pixels the interpolation covers
  /// The decision: CV_8UC1, 255 at covered pixels with Δ above the map's decision_threshold();
  /// empty when the map has none or nothing covers the frame.
  cv::Mat novel;
  /// Share of the covered pixels in `novel` (NaN when it is empty): with nothing new in view, the
  /// false-alarm rate.
  double novel_share = std::numeric_limits<double>::quiet_NaN();
};

class IlluminationMap {
 public:
  explicit IlluminationMap(const IlluminationMapOptions& options = {});

  /// Starts the next lighting (the first call starts lighting 0). Frames added before any call
  /// belong to lighting 0. Ending a lighting renders its virtual images (the first also places
  /// the viewpoints); if that throws, the map is as before the call. Throws std::logic_error
  /// after Build(), std::invalid_argument for a lighting without frames or beyond kMaxLightings.
  void BeginLighting();
  /// A training frame of the current lighting: RGB, depth and pose required (std::invalid_argument
  /// naming the frame otherwise); all frames must share one camera.
  void AddTrainingFrame(const core::Frame& frame);
  /// Makes the invariant images and models. Throws std::invalid_argument, leaving the map as it
  /// was, with fewer than two lightings (one lighting gives no invariant image) or when no
  /// viewpoint is covered by enough of them; viewpoints below min_viewpoint_coverage are dropped
  /// and counted. With at least min_lightings + 1 lightings (and threshold.viewpoints > 0) it
  /// also learns decision_threshold() by leaving one lighting out (lighting_threshold.h).
  void Build();
  bool built() const { return built_; }

  /// Judges a frame (RGB and pose; depth not needed). A frame no viewpoint faces gets coverage
  /// 0 and an empty novelty. Throws std::logic_error before Build(), std::invalid_argument for a
  /// frame without pose or of another image size.
  IlluminationMapResult Detect(const core::Frame& frame) const;

  int lightings() const { return lightings_; }
  int size() const { return store_.size(); }
  /// Viewpoint i's geometry and planes: "invariant" (CV_32FC4: r̂ and the coverage 0/1) and
  /// "shapes" (CV_8UC(M): per lighting 255 where i_Y > T_Y).
  const views::ReferenceView& view(int i) const { return store_.view(i); }
  const IlluminationViewpointModel& model(int i) const { return models_.at(std::size_t(i)); }
  /// Adds a built viewpoint (a loaded map's): planes as view() describes, a usable model, the
  /// same image size and lightings as the others. Throws std::invalid_argument otherwise,
  /// std::logic_error on a map that is acquiring.
  void AddViewpoint(views::ReferenceView view, IlluminationViewpointModel model, int lightings);
  /// The viewpoints (their geometry: poses for drawing, selection).
  const views::ReferenceViewStore& store() const { return store_; }
  int dropped_viewpoints() const { return dropped_; }
  /// τ on Δ at options().threshold.false_alarm_rate (nats); NaN when none was learnt (too few
  /// lightings, or threshold.viewpoints = 0). A pixel with Δ > τ is judged novel.
  double decision_threshold() const { return decision_threshold_; }
  /// A loaded map's τ: finite and ≥ 0, or NaN for none (std::invalid_argument otherwise).
  void SetDecisionThreshold(double threshold);
  const IlluminationMapOptions& options() const { return options_; }
  const ZernikeMoments& zernike() const { return zernike_; }
  std::size_t BytesUsed() const;

 private:
  struct RenderedLighting {
    std::vector<cv::Mat> rgb, valid;  // per viewpoint
  };
  views::ReferenceViewStore PlacedViewpoints() const;  // along the current frames' path
  // The current lighting's virtual images at every viewpoint.
  RenderedLighting RenderLighting(const views::ReferenceViewStore& viewpoints) const;
  // Each viewpoint's virtual image and mask of one lighting onto its lists.
  // τ from the kept viewpoints' virtual images (`images`, `masks` indexed as `kept_index`).
  double LearnThreshold(const std::vector<std::vector<cv::Mat>>& images,
                        const std::vector<std::vector<cv::Mat>>& masks,
                        const std::vector<int>& kept_index) const;
  static void Append(const RenderedLighting& rendered, std::vector<std::vector<cv::Mat>>& images,
                     std::vector<std::vector<cv::Mat>>& masks);

  IlluminationMapOptions options_;
  ZernikeMoments zernike_;
  bool built_ = false;
  int lightings_ = 0;
  std::vector<core::Frame> frames_;                                // the current lighting's
  views::ReferenceViewStore store_;                                // the viewpoints
  std::vector<std::vector<cv::Mat>> virtual_rgb_, virtual_valid_;  // [viewpoint][lighting]
  std::vector<IlluminationViewpointModel> models_;
  int dropped_ = 0;
  double decision_threshold_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace novelty::illumination
