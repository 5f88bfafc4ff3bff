#include "maps/views/view_synthesis.h"

#include <stdexcept>

namespace novelty::views {

SynthesisResult SynthesiseView(DepthMeshWarper& warper,
                               const std::vector<const ReferenceView*>& refs,
                               const std::vector<const MeshPlan*>& plans,
                               const std::vector<double>& weights,
                               const core::PinholeCamera& camera,
                               const Eigen::Isometry3d& T_world_virtual,
                               const SynthesisOptions& options) {
  std::vector<SourceView> sources;
  std::vector<cv::Mat> planes;
  for (std::size_t k = 0; k < refs.size(); ++k) {
    const ReferenceView* r = refs[k];
    const auto rgb = r->planes.find("rgb");
    if (rgb == r->planes.end())
      throw std::invalid_argument("SynthesiseView: reference view " + std::to_string(k) +
                                  " has no \"rgb\" plane");
    sources.push_back({&r->camera, &r->T_world_cam, &r->depth, plans.empty() ? nullptr : plans[k]});
    planes.push_back(rgb->second);
  }
  std::vector<WarpField> warps;
  warper.WarpMany(sources, camera, T_world_virtual, warps);
  BlendOptions blend = options.blend;
  if (!weights.empty()) blend.weights = weights;
  const BlendResult b = BlendPlanes(warps, planes, blend);
  SynthesisResult out;
  cv::Mat value = b.value.clone();
  value.setTo(cv::Scalar::all(0), ~b.valid);
  value.convertTo(out.rgb, CV_8UC3);  // rounds and saturates
  out.valid = b.valid;
  out.coverage = double(b.covered) / (double(camera.width) * camera.height);
  return out;
}

SynthesisResult SynthesiseView(const std::vector<const ReferenceView*>& refs,
                               const core::PinholeCamera& camera,
                               const Eigen::Isometry3d& T_world_virtual,
                               const SynthesisOptions& options) {
  DepthMeshWarper warper(options.warp, WarpOutputsFor(options.blend));
  return SynthesiseView(warper, refs, {}, {}, camera, T_world_virtual, options);
}

SynthesisResult SynthesiseSelected(DepthMeshWarper& warper, const std::vector<ReferenceView>& refs,
                                   const std::vector<Eigen::Isometry3d>& poses,
                                   const core::PinholeCamera& camera,
                                   const Eigen::Isometry3d& T_world_virtual,
                                   const ViewSelectionOptions& selection,
                                   const SynthesisOptions& options) {
  const ViewSelection sel = SelectViewsForRays(poses, camera, T_world_virtual, selection);
  if (sel.views.empty()) {
    SynthesisResult none;
    none.rgb = cv::Mat::zeros(camera.height, camera.width, CV_8UC3);
    none.valid = cv::Mat::zeros(none.rgb.size(), CV_8UC1);
    return none;
  }
  std::vector<const ReferenceView*> chosen;
  for (int i : sel.views) chosen.push_back(&refs.at(std::size_t(i)));
  return SynthesiseView(warper, chosen, {}, sel.Weights(selection), camera, T_world_virtual,
                        options);
}

}  // namespace novelty::views
