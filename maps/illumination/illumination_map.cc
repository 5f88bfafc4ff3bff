#include "maps/illumination/illumination_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "maps/views/depth_mesh_warper.h"
#include "maps/views/view_blender.h"

namespace novelty::illumination {
namespace {

constexpr char kInvariantPlane[] = "invariant";
constexpr char kShapesPlane[] = "shapes";
constexpr char kTexturePlane[] = "texture";  // IlluminationModel::texture_scale, when learnt

std::string FrameName(const core::Frame& f) {
  return "frame " + std::to_string(f.index) + (f.label.empty() ? "" : " (" + f.label + ")");
}

// Throws unless the frame's image is 8-bit RGB of its camera's size (`name` says which frame).
void CheckFrameImage(const core::Frame& f, const std::string& name) {
  if (f.rgb.type() != CV_8UC3 || f.rgb.cols != f.camera.width || f.rgb.rows != f.camera.height)
    throw std::invalid_argument(name + " must be 8-bit RGB of its camera's size");
}

double AngleDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.rotation().transpose() * b.rotation()).angle() * 180.0 / M_PI;
}

// r̂ and its coverage (0/1) as one float plane, so that one blend interpolates both.
cv::Mat InvariantPlane(const InvariantImage& inv) {
  std::vector<cv::Mat> channels;
  cv::split(inv.log_invariant, channels);
  cv::Mat covered;
  inv.covered.convertTo(covered, CV_32F, 1.0 / 255.0);
  channels.push_back(covered);
  cv::Mat plane;
  cv::merge(channels, plane);
  return plane;
}

// The missing texture's scale where the invariant image covers, 0 elsewhere: blended, it is
// divided by the blended coverage as r̂ is, so that a viewpoint without a value does not pull it.
cv::Mat TexturePlane(const IlluminationModel& model, const InvariantImage& inv) {
  cv::Mat plane = model.texture_scale.clone();
  plane.setTo(0.0f, inv.covered == 0);
  return plane;
}

cv::Mat ShapesPlane(const std::vector<cv::Mat>& shapes) {
  cv::Mat plane;
  cv::merge(shapes, plane);
  return plane;
}

// Weighted mean of the gamma parameters and thresholds ("interpolated gamma parameters", 6.3);
// the saturation's over the models that have one (colourless viewpoints have none).
IlluminationModel MeanModel(const std::vector<const IlluminationModel*>& models,
                            const std::vector<double>& weights) {
  IlluminationModel m = *models.front();
  m.luminance.alpha = m.luminance.beta = m.saturation.alpha = m.saturation.beta = 0.0;
  m.mean_information = m.threshold = 0.0;
  double total = 0.0, saturation_total = 0.0;
  bool texture = true;
  for (std::size_t k = 0; k < models.size(); ++k) {
    const double w = weights[k];
    const IlluminationModel& o = *models[k];
    total += w;
    m.luminance.alpha += w * o.luminance.alpha;
    m.luminance.beta += w * o.luminance.beta;
    m.mean_information += w * o.mean_information;
    m.threshold += w * o.threshold;
    if (o.saturation.alpha > 0.0) {
      saturation_total += w;
      m.saturation.alpha += w * o.saturation.alpha;
      m.saturation.beta += w * o.saturation.beta;
    }
    texture = texture && !o.texture.empty();
  }
  for (double* v : {&m.luminance.alpha, &m.luminance.beta, &m.mean_information, &m.threshold})
    *v /= total;
  if (saturation_total > 0.0) {
    m.saturation.alpha /= saturation_total;
    m.saturation.beta /= saturation_total;
  }
  // The missing texture only where every viewpoint learnt it (its scale plane is blended).
  m.texture = {};
  m.texture_floor = 0.0;
  if (texture) {
    std::vector<const stats::TailTable*> tables;
    for (std::size_t k = 0; k < models.size(); ++k) {
      tables.push_back(&models[k]->texture);
      m.texture_floor += weights[k] * models[k]->texture_floor / total;
    }
    m.texture = stats::MeanTail(tables, weights);
  }
  return m;
}

// A loaded viewpoint's missing-texture model: its plane (scale > 0 and finite where the
// invariant image covers, ≥ 0 elsewhere), a sorted finite tail table, floor and block as the
// option table allows; like the first viewpoint's (a map's viewpoints average them). Throws
// std::invalid_argument naming `what`.
void CheckTextureModel(const views::ReferenceView& view, const IlluminationModel& m,
                       const IlluminationModel* first, const std::string& what) {
  const auto plane = view.planes.find(kTexturePlane);
  const stats::TailTable& tail = m.texture;
  if (tail.empty() != (plane == view.planes.end()))
    throw std::invalid_argument(what +
                                ": a missing-texture model and its 'texture' plane come "
                                "together");
  if (first && first->texture.values.size() != tail.values.size())
    throw std::invalid_argument(what + ": missing texture unlike viewpoint 0's (" +
                                std::to_string(tail.values.size()) + " tail entries against " +
                                std::to_string(first->texture.values.size()) + ")");
  if (tail.empty()) return;
  if (first && first->texture_block != m.texture_block)
    throw std::invalid_argument(what + ": missing-texture block " +
                                std::to_string(m.texture_block) + ", viewpoint 0's " +
                                std::to_string(first->texture_block));
  const cv::Mat& scale = plane->second;
  cv::Mat covered;
  cv::extractChannel(view.planes.at(kInvariantPlane), covered, 3);
  double least = 0.0;
  if (scale.type() != CV_32FC1 || scale.size() != covered.size() || !cv::checkRange(scale) ||
      (cv::minMaxLoc(scale, &least), least < 0.0) ||
      (cv::minMaxLoc(scale, &least, nullptr, nullptr, nullptr, covered >= 0.5f), least <= 0.0) ||
      tail.values.size() < 2 || !std::is_sorted(tail.values.begin(), tail.values.end()) ||
      !std::all_of(tail.values.begin(), tail.values.end(),
                   [](float v) { return std::isfinite(v); }) ||
      !(tail.max_information > 0.0 && std::isfinite(tail.max_information)) ||
      !(m.texture_floor > 0.0 && std::isfinite(m.texture_floor)) || m.texture_block < 1 ||
      m.texture_block > kMaxTextureBlock || m.texture_block % 2 == 0)
    throw std::invalid_argument(what +
                                ": a missing-texture model needs a 'texture' plane (float, one "
                                "channel, > 0 where covered), a sorted finite tail table, a "
                                "floor > 0 and an odd block of at most " +
                                std::to_string(kMaxTextureBlock));
}

}  // namespace

IlluminationMap::IlluminationMap(const IlluminationMapOptions& options)
    : options_(options), zernike_(options.zernike) {
  // A frame's intensities are clipped as the invariant image's were (eq. 6.19 against 6.5).
  options_.novelty.min_intensity = options.invariant.min_intensity;
  if (!(options.viewpoint_distance >= 0.0) || !(options.viewpoint_angle_deg >= 0.0))
    throw std::invalid_argument(
        "IlluminationMap: viewpoint_distance and viewpoint_angle_deg must be >= 0");
  if (!(options.min_viewpoint_coverage >= 0.0 && options.min_viewpoint_coverage <= 1.0))
    throw std::invalid_argument("IlluminationMap: min_viewpoint_coverage must be in [0, 1]");
  if (!(options.threshold.false_alarm_rate > 0.0 && options.threshold.false_alarm_rate < 1.0) ||
      options.threshold.viewpoints < 0)
    throw std::invalid_argument(
        "IlluminationMap: threshold.false_alarm_rate must be in (0, 1), threshold.viewpoints >= 0");
}

void IlluminationMap::BeginLighting() {
  if (built_) throw std::logic_error("IlluminationMap: BeginLighting after Build");
  if (lightings_ == 0) {
    lightings_ = 1;
    if (frames_.empty()) return;  // lighting 0 starts now
  }
  if (frames_.empty())
    throw std::invalid_argument("IlluminationMap: lighting " + std::to_string(lightings_ - 1) +
                                " has no frames");
  if (lightings_ >= kMaxLightings)
    throw std::invalid_argument("IlluminationMap: at most " + std::to_string(kMaxLightings) +
                                " lightings");
  // Rendered aside and committed only when it all worked: a frame that fails leaves the map as
  // it was.
  views::ReferenceViewStore placed = store_.size() ? store_ : PlacedViewpoints();
  RenderedLighting rendered = RenderLighting(placed);
  store_ = std::move(placed);
  Append(rendered, virtual_rgb_, virtual_valid_);
  frames_.clear();
  ++lightings_;
}

void IlluminationMap::AddTrainingFrame(const core::Frame& frame) {
  if (built_) throw std::logic_error("IlluminationMap: AddTrainingFrame after Build");
  const std::string name = "IlluminationMap: " + FrameName(frame);
  if (!frame.T_world_cam) throw std::invalid_argument(name + " has no pose");
  if (frame.rgb.empty() || frame.depth.empty())
    throw std::invalid_argument(name + " needs an image and a depth map");
  CheckFrameImage(frame, name);
  views::ReferenceViewOf(frame).Check(name);  // rigid pose, float depth of the image's size
  const core::PinholeCamera& first =
      !frames_.empty() ? frames_.front().camera : (size() ? store_.camera(0) : frame.camera);
  if (frame.camera.width != first.width || frame.camera.height != first.height)
    throw std::invalid_argument(name + " is " + std::to_string(frame.camera.width) + "x" +
                                std::to_string(frame.camera.height) + ", the first frame " +
                                std::to_string(first.width) + "x" + std::to_string(first.height));
  if (lightings_ == 0) lightings_ = 1;
  frames_.push_back(frame);
}

views::ReferenceViewStore IlluminationMap::PlacedViewpoints() const {
  views::ReferenceViewStore placed;
  const core::Frame* last = nullptr;
  for (const core::Frame& f : frames_) {
    if (last) {
      const double d = (f.T_world_cam->translation() - last->T_world_cam->translation()).norm();
      if (d < options_.viewpoint_distance &&
          AngleDeg(*f.T_world_cam, *last->T_world_cam) < options_.viewpoint_angle_deg)
        continue;
    }
    views::ReferenceView v;
    v.camera = f.camera;
    v.T_world_cam = *f.T_world_cam;
    v.depth = f.depth.clone();
    placed.Add(std::move(v));
    last = &f;
  }
  return placed;
}

IlluminationMap::RenderedLighting IlluminationMap::RenderLighting(
    const views::ReferenceViewStore& viewpoints) const {
  std::vector<views::ReferenceView> refs;
  std::vector<Eigen::Isometry3d> poses;
  refs.reserve(frames_.size());
  for (const core::Frame& f : frames_) {
    refs.push_back(views::ReferenceViewOf(f));
    poses.push_back(*f.T_world_cam);
  }
  views::DepthMeshWarper warper(options_.synthesis.warp,
                                views::WarpOutputsFor(options_.synthesis.blend));
  RenderedLighting out;
  for (int v = 0; v < viewpoints.size(); ++v) {
    const views::SynthesisResult r =
        views::SynthesiseSelected(warper, refs, poses, viewpoints.camera(v), viewpoints.pose(v),
                                  options_.selection, options_.synthesis);
    out.rgb.push_back(r.rgb);
    out.valid.push_back(r.valid);
  }
  return out;
}

void IlluminationMap::Append(const RenderedLighting& rendered,
                             std::vector<std::vector<cv::Mat>>& images,
                             std::vector<std::vector<cv::Mat>>& masks) {
  images.resize(rendered.rgb.size());
  masks.resize(rendered.rgb.size());
  for (std::size_t v = 0; v < rendered.rgb.size(); ++v) {
    images[v].push_back(rendered.rgb[v]);
    masks[v].push_back(rendered.valid[v]);
  }
}

void IlluminationMap::Build() {
  if (built_) throw std::logic_error("IlluminationMap: Build called twice");
  // Everything into locals first: a Build that throws leaves the map as it was.
  views::ReferenceViewStore viewpoints = store_.size() ? store_ : PlacedViewpoints();
  std::vector<std::vector<cv::Mat>> images = virtual_rgb_, masks = virtual_valid_;
  if (!frames_.empty()) Append(RenderLighting(viewpoints), images, masks);
  const int lightings = images.empty() ? 0 : int(images.front().size());
  if (lightings < 2)
    throw std::invalid_argument("IlluminationMap: " + std::to_string(lightings) +
                                " lighting(s) with frames; the median of one lighting is that "
                                "image's gradient, not an invariant one — acquire at least two");
  views::ReferenceViewStore kept;
  std::vector<IlluminationViewpointModel> models;
  std::vector<int> kept_index;
  int dropped = 0;
  std::string first_error;
  for (int v = 0; v < viewpoints.size(); ++v) {
    views::ReferenceView view = viewpoints.Decoded(v);
    try {
      const InvariantImage inv =
          ComputeInvariantImage(images[std::size_t(v)], masks[std::size_t(v)], options_.invariant);
      const double coverage = cv::countNonZero(inv.covered) / double(inv.covered.total());
      // Of the pixels the viewpoint's depth knows: elsewhere no lighting can cover it (a fixed
      // camera's mask, the sky).
      const cv::Mat known = view.depth > 0.0f;  // NaN compares false
      const int known_pixels = cv::countNonZero(known);
      const double share =
          known_pixels ? cv::countNonZero(inv.covered & known) / double(known_pixels) : 0.0;
      if (share < options_.min_viewpoint_coverage || coverage == 0.0) {
        if (first_error.empty())
          first_error = "viewpoint " + std::to_string(v) + ": " + std::to_string(int(100 * share)) +
                        " % of its known pixels covered, " + "below min_viewpoint_coverage";
        ++dropped;
        continue;
      }
      IlluminationViewpointModel m;
      m.model = LearnIlluminationModel(inv, masks[std::size_t(v)], options_.model);
      m.coverage = coverage;
      view.planes[kInvariantPlane] = InvariantPlane(inv);
      view.planes[kShapesPlane] = ShapesPlane(m.model.shapes);
      m.model.shapes.clear();
      if (!m.model.texture_scale.empty()) view.planes[kTexturePlane] = TexturePlane(m.model, inv);
      m.model.texture_scale.release();
      kept.Add(std::move(view));
      models.push_back(std::move(m));
      kept_index.push_back(v);
    } catch (const std::invalid_argument& e) {
      if (first_error.empty()) first_error = "viewpoint " + std::to_string(v) + ": " + e.what();
      ++dropped;
    }
  }
  if (kept.size() == 0)
    throw std::invalid_argument("IlluminationMap: no viewpoint has an invariant image (" +
                                std::to_string(dropped) + " dropped" +
                                (first_error.empty() ? "" : "; first: " + first_error) + ")");
  const double threshold = LearnThreshold(images, masks, kept_index);
  store_ = std::move(kept);
  models_ = std::move(models);
  dropped_ = dropped;
  decision_threshold_ = threshold;
  lightings_ = lightings;
  virtual_rgb_.clear();
  virtual_valid_.clear();
  frames_.clear();
  built_ = true;
}

double IlluminationMap::LearnThreshold(const std::vector<std::vector<cv::Mat>>& images,
                                       const std::vector<std::vector<cv::Mat>>& masks,
                                       const std::vector<int>& kept_index) const {
  const LightingThresholdOptions& o = options_.threshold;
  const int lightings = int(images.front().size());
  if (o.viewpoints <= 0 || lightings - 1 < std::max(2, options_.invariant.min_lightings))
    return std::numeric_limits<double>::quiet_NaN();
  // Evenly spread over the kept viewpoints: the middle of each of n equal runs.
  const int n = std::min(o.viewpoints, int(kept_index.size()));
  std::vector<float> pooled;
  for (int k = 0; k < n; ++k) {
    const auto v =
        std::size_t(kept_index[std::size_t((2 * k + 1) * int(kept_index.size()) / (2 * n))]);
    try {
      const HeldOutNovelty held = HeldOutLightingNovelty(
          images[v], masks[v], options_.invariant, options_.model, options_.novelty, zernike_);
      pooled.insert(pooled.end(), held.values.begin(), held.values.end());
    } catch (const std::invalid_argument&) {
      // One lighting fewer can leave a viewpoint without an invariant image; the others speak.
    }
  }
  if (pooled.empty()) return std::numeric_limits<double>::quiet_NaN();
  return ThresholdAtFalseAlarmRate(std::move(pooled), o.false_alarm_rate);
}

void IlluminationMap::SetDecisionThreshold(double threshold) {
  if (!(std::isnan(threshold) || (std::isfinite(threshold) && threshold >= 0.0)))
    throw std::invalid_argument("IlluminationMap: a decision threshold must be >= 0 and finite");
  decision_threshold_ = threshold;
}

void IlluminationMap::AddViewpoint(views::ReferenceView view, IlluminationViewpointModel model,
                                   int lightings) {
  const std::string what = "illumination viewpoint " + std::to_string(store_.size());
  if (!built_ && (lightings_ > 0 || !frames_.empty()))
    throw std::logic_error("IlluminationMap: AddViewpoint while acquiring");
  view.Check(what);
  const auto inv = view.planes.find(kInvariantPlane);
  const auto shapes = view.planes.find(kShapesPlane);
  if (inv == view.planes.end() || shapes == view.planes.end() || inv->second.type() != CV_32FC4 ||
      shapes->second.depth() != CV_8U || shapes->second.channels() != lightings)
    throw std::invalid_argument(what +
                                ": needs planes 'invariant' (float, r̂ of three channels and the "
                                "coverage) and 'shapes' (8-bit, one channel per lighting)");
  CheckTextureModel(view, model.model, size() ? &models_.front().model : nullptr, what);
  if (size() && (view.camera.width != store_.camera(0).width ||
                 view.camera.height != store_.camera(0).height))
    throw std::invalid_argument(what + ": another image size than viewpoint 0's");
  const IlluminationModel& m = model.model;
  if (!(m.luminance.alpha > 0.0 && m.luminance.beta > 0.0 && std::isfinite(m.luminance.alpha) &&
        std::isfinite(m.luminance.beta) && m.luminance_step > 0.0 && m.saturation_step > 0.0 &&
        model.coverage > 0.0 && model.coverage <= 1.0))
    throw std::invalid_argument(what + ": no usable luminance gamma model, widths or coverage");
  if (lightings < 2 || lightings > kMaxLightings || (size() && lightings != lightings_))
    throw std::invalid_argument(what + ": " + std::to_string(lightings) + " lightings" +
                                (size() ? ", the map " + std::to_string(lightings_) : ""));
  lightings_ = lightings;
  store_.Add(std::move(view));
  models_.push_back(std::move(model));
  built_ = true;
}

IlluminationMapResult IlluminationMap::Detect(const core::Frame& frame) const {
  if (!built_) throw std::logic_error("IlluminationMap: Detect before Build");
  if (!frame.T_world_cam)
    throw std::invalid_argument("IlluminationMap: " + FrameName(frame) + " has no pose");
  CheckFrameImage(frame, "IlluminationMap: " + FrameName(frame));
  if (frame.rgb.cols != store_.camera(0).width || frame.rgb.rows != store_.camera(0).height)
    throw std::invalid_argument(
        "IlluminationMap: " + FrameName(frame) + " is " + std::to_string(frame.rgb.cols) + "x" +
        std::to_string(frame.rgb.rows) + ", the map's viewpoints " +
        std::to_string(store_.camera(0).width) + "x" + std::to_string(store_.camera(0).height));
  IlluminationMapResult out;
  const views::ViewSelection sel = views::SelectViewsForRays(
      store_.Poses(), frame.camera, *frame.T_world_cam, options_.selection);
  if (sel.views.empty()) return out;
  out.viewpoints = sel.views;
  const std::vector<double> weights = sel.Weights(options_.selection);

  views::DepthMeshWarper warper(options_.synthesis.warp,
                                views::WarpOutputsFor(options_.synthesis.blend));
  std::vector<views::SourceView> sources;
  std::vector<cv::Mat> invariant_planes, shape_planes, texture_planes;
  std::vector<const IlluminationModel*> models;
  for (int i : sel.views) {
    const views::ReferenceView& v = store_.view(i);
    sources.push_back({&v.camera, &v.T_world_cam, &v.depth, nullptr});
    invariant_planes.push_back(v.planes.at(kInvariantPlane));
    shape_planes.push_back(v.planes.at(kShapesPlane));
    const auto texture = v.planes.find(kTexturePlane);
    if (texture != v.planes.end()) texture_planes.push_back(texture->second);
    models.push_back(&models_[std::size_t(i)].model);
  }
  std::vector<views::WarpField> fields;
  warper.WarpMany(sources, frame.camera, *frame.T_world_cam, fields);
  views::BlendOptions blend = options_.synthesis.blend;
  blend.weights = weights;
  const views::BlendResult inv = views::BlendPlanes(fields, invariant_planes, blend);
  const views::BlendResult shp = views::BlendPlanes(fields, shape_planes, blend);

  // Covered where the viewpoints that see the pixel mostly had an invariant value there.
  std::vector<cv::Mat> channels;
  cv::split(inv.value, channels);
  cv::Mat covered = (channels.back() >= 0.5f) & inv.valid;  // NaN compares false
  // r̂ is 0 where a viewpoint has no value, so the blend is the coverage-weighted sum: divided by
  // the blended coverage it is the average over the viewpoints that have one.
  const cv::Mat coverage = channels.back();
  channels.pop_back();
  for (cv::Mat& c : channels) cv::divide(c, coverage, c);
  cv::Mat log_invariant;
  cv::merge(channels, log_invariant);
  log_invariant.setTo(cv::Scalar::all(0), ~covered);
  out.coverage = cv::countNonZero(covered) / double(covered.total());

  IlluminationModel model = MeanModel(models, weights);
  std::vector<cv::Mat> shapes;
  cv::split(shp.value, shapes);
  for (cv::Mat& s : shapes) s = (s >= 127.5f) & covered;
  model.shapes = std::move(shapes);
  if (!model.texture.empty()) {  // every viewpoint has its plane (MeanModel)
    cv::divide(views::BlendPlanes(fields, texture_planes, blend).value, coverage,
               model.texture_scale);
    model.texture_scale.setTo(1.0f, ~covered);  // not used there; finite
  }
  InvariantImage interpolated;
  interpolated.log_invariant = log_invariant;
  interpolated.covered = covered;
  out.viewpoint =
      MakeViewpoint(interpolated, std::move(model), options_.novelty.min_region_pixels, &zernike_);
  if (out.coverage == 0.0) return out;
  out.novelty = DetectIlluminationNovelty(frame.rgb, out.viewpoint, zernike_, options_.novelty);
  if (!std::isnan(decision_threshold_)) {
    out.novel = (out.novelty.novelty > decision_threshold_) & covered;
    out.novel_share = cv::countNonZero(out.novel) / double(cv::countNonZero(covered));
  }
  return out;
}

std::size_t IlluminationMap::BytesUsed() const {
  std::size_t bytes = store_.BytesUsed();
  for (const auto& v : virtual_rgb_)
    for (const cv::Mat& m : v) bytes += m.total() * m.elemSize();
  for (const core::Frame& f : frames_)
    bytes += f.rgb.total() * f.rgb.elemSize() + f.depth.total() * f.depth.elemSize();
  return bytes;
}

}  // namespace novelty::illumination
