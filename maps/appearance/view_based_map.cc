#include "maps/appearance/view_based_map.h"
#include "core/rigid_pose.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <opencv2/core/utility.hpp>
#include <stdexcept>
#include <string>

namespace novelty::appearance {

namespace {

bool SameCamera(const core::PinholeCamera& a, const core::PinholeCamera& b) {
  return a.width == b.width && a.height == b.height && a.fx == b.fx && a.fy == b.fy &&
         a.cx == b.cx && a.cy == b.cy;
}

bool SamePose(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.matrix() - b.matrix()).cwiseAbs().maxCoeff() < 1e-9;
}

}  // namespace

struct Prediction::Blend {
  std::vector<views::WarpField> warps;
  views::BlendOptions options;  // the map's, with the selected views' weights (ray counts)
  // Per requested plane: the selected views' planes, and the blend's images (shared with the
  // prediction's value and valid).
  std::vector<std::vector<cv::Mat>> planes;
  std::vector<views::BlendResult> results;
};

namespace {

// Prediction::depth: per pixel the first warp (in selection order) that covers it; and
// Prediction::depth_span: the nearest and farthest of the warps that cover it.
void CoveringDepths(const std::vector<views::WarpField>& warps, const core::PinholeCamera& camera,
                    Prediction& p) {
  p.depth = cv::Mat::zeros(camera.height, camera.width, CV_32FC1);
  p.depth_span = cv::Mat::zeros(camera.height, camera.width, CV_32FC2);
  for (int y = 0; y < p.depth.rows; ++y) {
    float* out = p.depth.ptr<float>(y);
    cv::Vec2f* span = p.depth_span.ptr<cv::Vec2f>(y);
    for (const views::WarpField& w : warps) {
      if (w.depth.empty())
        throw std::invalid_argument(
            "ViewBasedMap: a prediction with depth needs warps with depth (WarpOutputs::depth)");
      const float* d = w.depth.ptr<float>(y);
      for (int x = 0; x < p.depth.cols; ++x) {
        if (!(d[x] > 0.0f)) continue;
        if (out[x] == 0.0f) {
          out[x] = d[x];
          span[x] = cv::Vec2f(d[x], d[x]);
        } else {
          span[x][0] = std::min(span[x][0], d[x]);
          span[x][1] = std::max(span[x][1], d[x]);
        }
      }
    }
  }
}

cv::Mat SpanOf(const cv::Mat& depth) {
  cv::Mat span;
  cv::merge(std::vector<cv::Mat>{depth, depth}, span);
  return span;
}

}  // namespace

void Prediction::BlendRows(const cv::Range& rows) const {
  if (!blend_) return;
  for (std::size_t k = 0; k < blend_->planes.size(); ++k) {
    views::BlendRows(blend_->warps, blend_->planes[k], blend_->options, rows, blend_->results[k]);
  }
}

ViewBasedMap::ViewBasedMap(const ViewBasedMapOptions& options)
    : options_(options),
      store_(options.storage),
      warper_(options.warp, views::WarpOutputsFor(options.blend)) {}

ViewBasedMap::~ViewBasedMap() = default;

views::MeshPlan ViewBasedMap::PlanMesh(const cv::Mat& depth) const {
  return views::MeshPlanFor(depth, options_.warp);
}

Prediction ViewBasedMap::Predict(const core::PinholeCamera& camera,
                                 const Eigen::Isometry3d& T_world_cam,
                                 const std::vector<std::pair<std::string, int>>& names,
                                 bool with_depth) {
  Prediction p = PredictDeferred(camera, T_world_cam, names, with_depth);
  if (!p.complete()) {
    cv::parallel_for_(cv::Range(0, camera.height),
                      [&](const cv::Range& rows) { p.BlendRows(rows); });
    p.blend_.reset();
  }
  return p;
}

Prediction ViewBasedMap::PredictDeferred(const core::PinholeCamera& camera,
                                         const Eigen::Isometry3d& T_world_cam,
                                         const std::vector<std::pair<std::string, int>>& names,
                                         bool with_depth) {
  Prediction p;
  const views::ViewSelection selection =
      views::SelectViewsForRays(store_.Poses(), camera, T_world_cam, options_.selection);
  p.selected = selection.views;
  p.value.resize(names.size());
  if (p.selected.empty()) {
    for (std::size_t k = 0; k < names.size(); ++k) {
      cv::Mat& m = p.value[k];
      m.create(camera.height, camera.width, CV_32FC(names[k].second));
      m.reshape(1).setTo(std::numeric_limits<float>::quiet_NaN());  // Scalar: ≤ 4 channels
    }
    p.valid = cv::Mat::zeros(camera.height, camera.width, CV_8UC1);
    if (with_depth) {
      p.depth = cv::Mat::zeros(camera.height, camera.width, CV_32FC1);
      p.depth_span = cv::Mat::zeros(camera.height, camera.width, CV_32FC2);
    }
    return p;
  }
  // A camera exactly at a reference view (a static camera) needs no warp: the view's own
  // planes are the prediction, shared as stored, every pixel valid.
  for (int j : p.selected) {
    if (!SameCamera(store_.camera(j), camera) || !SamePose(store_.pose(j), T_world_cam)) continue;
    const views::ReferenceView& v = store_.view(j);
    Trim({j});
    p.selected = {j};
    for (std::size_t k = 0; k < names.size(); ++k) p.value[k] = v.planes.at(names[k].first);
    p.valid = cv::Mat(camera.height, camera.width, CV_8UC1, cv::Scalar(255));
    if (with_depth) {
      p.depth = v.depth;  // shared, as the planes: read only
      p.depth_span = SpanOf(v.depth);
    }
    return p;
  }
  std::vector<views::SourceView> sources;
  for (int j : p.selected) store_.view(j);  // decoded (the cache may hold them already)
  Trim(p.selected);
  for (int j : p.selected) {
    const views::ReferenceView& v = store_.view(j);
    views::MeshPlan& plan = plans_[std::size_t(j)];
    if (!plan.Fits(v.depth.size(), options_.warp.planar_block, options_.warp.planar_tolerance)) {
      plan = PlanMesh(v.depth);  // first warp
    }
    sources.push_back({&v.camera, &v.T_world_cam, &v.depth, &plan});
  }
  // The last prediction's buffers, unless its caller still holds it.
  if (!last_blend_ || last_blend_.use_count() > 1) {
    last_blend_ = std::make_shared<Prediction::Blend>();
  } else {
    // Its last holder may have let it go on another thread, after blending rows there: those
    // reads come before the rewrite below (use_count() alone does not order them).
    std::atomic_thread_fence(std::memory_order_acquire);
  }
  Prediction::Blend& b = *last_blend_;
  if (with_depth && !warper_.outputs().depth) {  // from now on: a caller reads it every frame
    views::WarpOutputs outputs = warper_.outputs();
    outputs.depth = true;
    warper_.set_outputs(outputs);
  }
  warper_.WarpMany(sources, camera, T_world_cam, b.warps);
  p.warped = true;
  if (with_depth) CoveringDepths(b.warps, camera, p);
  b.options = options_.blend;
  if (b.options.weights.empty()) b.options.weights = selection.Weights(options_.selection);
  b.results.resize(std::max(b.results.size(), names.size()));
  b.planes.resize(names.size());
  for (std::size_t k = 0; k < names.size(); ++k) {
    b.planes[k].clear();
    for (int j : p.selected) b.planes[k].push_back(store_.view(j).planes.at(names[k].first));
    views::BlendResult& r = b.results[k];  // written in place unless someone shares its images
    views::PrepareBlend(b.warps, b.planes[k], b.options, r);
    p.value[k] = r.value;
    p.valid = r.valid;  // the same for every plane: it depends on the warps only
  }
  p.blend_ = last_blend_;
  return p;
}

void ViewBasedMap::Trim(const std::vector<int>& keep) {
  for (int j : store_.Trim(keep)) plans_[std::size_t(j)] = {};
}

void ViewBasedMap::Restore(std::vector<views::ReferenceView> views,
                           std::vector<Eigen::Isometry3d> anchors,
                           std::vector<views::EncodedView> encoded) {
  if (views.size() != anchors.size() || (!encoded.empty() && encoded.size() != views.size())) {
    throw std::invalid_argument("ViewBasedMap::Restore: " + std::to_string(views.size()) +
                                " views, " + std::to_string(anchors.size()) + " anchors, " +
                                std::to_string(encoded.size()) + " encodings");
  }
  for (std::size_t j = 0; j < anchors.size(); ++j) {
    if (!core::IsRigid(anchors[j]))
      throw std::invalid_argument("view " + std::to_string(j) +
                                  ": anchor is not a rigid transform");
  }
  views::ReferenceViewStore store(options_.storage);
  for (std::size_t j = 0; j < views.size(); ++j) {
    store.Add(std::move(views[j]), encoded.empty() ? views::EncodedView{} : std::move(encoded[j]));
    store.Trim();  // a compact map holds its views compact while it loads
  }
  std::vector<views::MeshPlan> plans(std::size_t(store.size()));  // made at each view's first warp
  store_ = std::move(store);
  anchors_ = std::move(anchors);
  plans_ = std::move(plans);
}

ViewBasedMap::UpdateResult ViewBasedMap::Update(const core::PinholeCamera& camera,
                                                const Eigen::Isometry3d& T_world_cam, cv::Mat depth,
                                                std::map<std::string, cv::Mat> payload,
                                                const std::vector<int>& selected,
                                                views::MeshPlan plan) {
  if (!learning_) return {};
  double nearest = std::numeric_limits<double>::infinity();
  int nearest_view = -1;
  for (int j = 0; j < store_.size(); ++j) {
    const double d = (anchors_[std::size_t(j)].translation() - T_world_cam.translation()).norm();
    if (d < nearest) {
      nearest = d;
      nearest_view = j;
    }
  }
  views::ReferenceView v;
  v.camera = camera;
  v.T_world_cam = T_world_cam;
  v.depth = std::move(depth);
  v.planes = std::move(payload);
  UpdateResult r;
  bool add = nearest_view < 0 || nearest >= options_.new_view_distance;
  if (!add) {
    const Eigen::Vector3d z0 = anchors_[std::size_t(nearest_view)].linear().col(2);
    const double angle = std::acos(std::clamp(z0.dot(T_world_cam.linear().col(2)), -1.0, 1.0));
    add = angle >= options_.new_view_angle;
  }
  if (add || selected.empty()) {
    r.added = true;
    r.view = store_.Add(std::move(v));
    anchors_.push_back(T_world_cam);
    plans_.push_back(std::move(plan));
  } else {
    r.view = selected.front();
    store_.Replace(r.view, std::move(v));
    plans_[std::size_t(r.view)] = std::move(plan);  // the depth changed
  }
  std::vector<int> keep = selected;
  keep.push_back(r.view);
  Trim(keep);
  return r;
}

}  // namespace novelty::appearance
