// View synthesis (thesis ch. 3): a virtual 8-bit RGB image from reference views with depth —
// one warp per view (3.3.2, first pass) and the blend of their "rgb" planes (second pass). What
// novelty-synth runs, so that its tests measure what the program gives.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

#include "core/eigen_abi.h"
#include "maps/views/depth_mesh_warper.h"
#include "maps/views/mesh_plan.h"
#include "maps/views/reference_view_store.h"
#include "maps/views/view_blender.h"
#include "maps/views/view_selection.h"

namespace novelty::views {

struct SynthesisOptions {
  WarpOptions warp;    ///< mesh cut at depth jumps (max_relative_depth_jump 0.05)
  BlendOptions blend;  ///< depth tolerance and view-angle weighting (view_blender.h)
};

struct SynthesisResult {
  cv::Mat rgb;    ///< CV_8UC3, black where no view covers
  cv::Mat valid;  ///< CV_8UC1, 255 where a view covers
  /// Covered pixels over all pixels: report it beside any quality measured over `valid`.
  double coverage = 0.0;
};

/// Synthesises `camera`'s view at T_world_virtual from `refs` (each with an "rgb" plane).
/// `weights`: blend weight per view (empty: equal, or options.blend.weights); `plans`: the refs'
/// mesh plans where a caller keeps them (else empty). The warper must have been made with
/// (options.warp, WarpOutputsFor(options.blend)). Throws std::invalid_argument on a view without
/// an "rgb" plane or inputs that do not fit (see BlendPlanes).
SynthesisResult SynthesiseView(DepthMeshWarper& warper,
                               const std::vector<const ReferenceView*>& refs,
                               const std::vector<const MeshPlan*>& plans,
                               const std::vector<double>& weights,
                               const core::PinholeCamera& camera,
                               const Eigen::Isometry3d& T_world_virtual,
                               const SynthesisOptions& options);

/// The same with a warper made here (one-off syntheses, tests).
SynthesisResult SynthesiseView(const std::vector<const ReferenceView*>& refs,
                               const core::PinholeCamera& camera,
                               const Eigen::Isometry3d& T_world_virtual,
                               const SynthesisOptions& options = {});

/// The virtual image at T_world_virtual from the views of `refs` (at `poses`) that view selection
/// picks for its rays (3.3), weighted as it says — ch. 3 for one pose. No view picked: black,
/// nothing valid, coverage 0.
SynthesisResult SynthesiseSelected(DepthMeshWarper& warper, const std::vector<ReferenceView>& refs,
                                   const std::vector<Eigen::Isometry3d>& poses,
                                   const core::PinholeCamera& camera,
                                   const Eigen::Isometry3d& T_world_virtual,
                                   const ViewSelectionOptions& selection,
                                   const SynthesisOptions& options);

}  // namespace novelty::views
