// Novelty under changing light at one viewpoint (thesis 6.3): the illumination image of a new
// frame against the invariant image (eq. 6.19), the information of its luminance and saturation
// under the viewpoint's gamma models (eq. 6.16-6.17), its regions above T_Y, each matched by
// Zernike descriptors (eq. 6.21-6.23) against the highlight and shadow shapes the viewpoint
// stored, inside the intersection of their bounding boxes (steps 3a-d), and the novelty
//   Δ = e/ê · sqrt(i_Y² + i_S²)   (eq. 6.24).
// A region that matches a stored shape well (small e) is lighting and is damped. The thesis
// leaves open what a region meets where no shape was stored: the empty shape, whose descriptor is
// 0, so e = |d'| — a region unlike anything stored keeps a large e. ê is the largest e of the
// frame's regions; pixels outside every region keep e/ê = 1 (their information is low anyway).
// With a model that learnt the missing texture (IlluminationModelOptions::missing_texture, beyond
// the thesis), its information i_T joins the sum: Δ = e/ê · sqrt(i_Y² + i_S² + i_T²).
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "maps/illumination/illumination_model.h"
#include "maps/illumination/zernike_moments.h"

namespace novelty::illumination {

/// One connected highlight or shadow region a viewpoint stored (from model.shapes).
struct StoredShape {
  cv::Rect box;
  cv::Mat mask;  ///< CV_8UC1 of box's size, 255 inside the region
  /// Its Zernike descriptor over its own box — the descriptor steps 3b-c need whenever the
  /// new region's box holds this one's — or empty (computed when needed).
  std::vector<float> descriptor;
};

/// What the illumination-invariant map keeps at one viewpoint.
struct ViewpointIllumination {
  cv::Mat log_invariant;  ///< r̂ (InvariantImage::log_invariant)
  cv::Mat covered;        ///< InvariantImage::covered
  IlluminationModel model;
  std::vector<StoredShape> shapes;  ///< the connected regions of model.shapes
};

struct IlluminationNoveltyOptions {
  /// Intensities below this (0…255) are clipped, as when the invariant image was made.
  double min_intensity = 3.0;
  /// Regions (new or stored) of fewer pixels are not shape-matched: their shape says nothing.
  int min_region_pixels = 16;
  /// A window BB_I must hold at least this share of the new region's pixels and of the stored
  /// shape's (the thesis: any non-empty window). Each part is scaled to the unit disc, so a
  /// sliver holding a pixel of each would match perfectly and say nothing.
  double min_window_share = 0.5;
  /// ê of eq. 6.24.
  enum class ShapeScale {
    kFrameMaximum,  ///< the largest e of the frame (the thesis)
    /// per region its own distance to the empty shape, |d'|: e/|d'| in [0, 1] says how much
    /// better than nothing the best stored shape explains it, whatever else the frame holds
    /// (with the frame's maximum a frame with one region is never damped).
    kEmptyShape,
  };
  ShapeScale shape_scale = ShapeScale::kFrameMaximum;
};

/// Builds a viewpoint from an invariant image and its model; splits the shapes into connected
/// regions of at least min_region_pixels (8-connected), with their descriptors when `zernike`
/// is given (pass the one detection will use).
ViewpointIllumination MakeViewpoint(const InvariantImage& invariant, IlluminationModel model,
                                    int min_region_pixels = 16,
                                    const ZernikeMoments* zernike = nullptr);

struct IlluminationNovelty {
  cv::Mat information_y, information_s;  ///< eq. 6.17, CV_32FC1 (i_S 0 for grey images)
  /// i_T, the tail information of the texture the frame hides (IlluminationModel::texture), 0
  /// when the model has none.
  cv::Mat information_t;
  cv::Mat regions;        ///< CV_8UC1, 255 where i_Y > T_Y
  cv::Mat shape_factor;   ///< e/ê in regions, 1 elsewhere
  cv::Mat novelty;        ///< Δ (eq. 6.24), CV_32FC1, 0 where not covered
  int region_count = 0;   ///< regions of at least min_region_pixels
  int matched_count = 0;  ///< of them, those a stored shape explains better than none
};

/// Throws std::invalid_argument when the image does not fit the viewpoint.
IlluminationNovelty DetectIlluminationNovelty(const cv::Mat& image,
                                              const ViewpointIllumination& viewpoint,
                                              const ZernikeMoments& zernike,
                                              const IlluminationNoveltyOptions& options = {});

}  // namespace novelty::illumination
