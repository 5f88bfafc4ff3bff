#include "maps/illumination/illumination_map.h"

#include <cmath>
#include <stdexcept>

#include "maps/views/depth_mesh_warper.h"
#include "maps/views/view_blender.h"

namespace novelty::illumination {
namespace {

constexpr char kInvariantPlane[] = "invariant";
constexpr char kShapesPlane[] = "shapes";

std::string FrameName(const core::Frame& f) {
  return "frame " + std::to_string(f.index) + (f.label.empty() ? "" : " (" + f.label + ")");
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

cv::Mat ShapesPlane(const std::vector<cv::Mat>& shapes) {
  cv::Mat plane;
  cv::merge(shapes, plane);
  return plane;
}

// Weighted mean of the gamma parameters and thresholds ("interpolated gamma parameters", 6.3).
IlluminationModel MeanModel(const std::vector<const IlluminationModel*>& models,
                            const std::vector<double>& weights) {
  IlluminationModel m = *models.front();
  double total = 0.0;
  m.luminance.alpha = m.luminance.beta = m.saturation.alpha = m.saturation.beta = 0.0;
  m.mean_information = m.threshold = 0.0;
  for (std::size_t k = 0; k < models.size(); ++k) {
    const double w = weights[k];
    total += w;
    m.luminance.alpha += w * models[k]->luminance.alpha;
    m.luminance.beta += w * models[k]->luminance.beta;
    m.saturation.alpha += w * models[k]->saturation.alpha;
    m.saturation.beta += w * models[k]->saturation.beta;
    m.mean_information += w * models[k]->mean_information;
    m.threshold += w * models[k]->threshold;
  }
  for (double* v : {&m.luminance.alpha, &m.luminance.beta, &m.saturation.alpha, &m.saturation.beta,
                    &m.mean_information, &m.threshold})
    *v /= total;
  return m;
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
  if (lightings_ == 1) PlaceViewpoints();
  RenderLighting();
  ++lightings_;
}

void IlluminationMap::AddTrainingFrame(const core::Frame& frame) {
  if (built_) throw std::logic_error("IlluminationMap: AddTrainingFrame after Build");
  if (!frame.T_world_cam)
    throw std::invalid_argument("IlluminationMap: " + FrameName(frame) + " has no pose");
  if (frame.rgb.empty() || frame.depth.empty())
    throw std::invalid_argument("IlluminationMap: " + FrameName(frame) +
                                " needs an image and a depth map");
  if (frame.rgb.type() != CV_8UC3 || frame.depth.size() != frame.rgb.size())
    throw std::invalid_argument("IlluminationMap: " + FrameName(frame) +
                                " must be 8-bit RGB with a depth map of its size");
  const core::PinholeCamera& first =
      !frames_.empty() ? frames_.front().camera : (size() ? store_.camera(0) : frame.camera);
  if (frame.camera.width != first.width || frame.camera.height != first.height)
    throw std::invalid_argument("IlluminationMap: " + FrameName(frame) + " is " +
                                std::to_string(frame.camera.width) + "x" +
                                std::to_string(frame.camera.height) + ", the first frame " +
                                std::to_string(first.width) + "x" + std::to_string(first.height));
  if (lightings_ == 0) lightings_ = 1;
  frames_.push_back(frame);
}

void IlluminationMap::PlaceViewpoints() {
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
    store_.Add(std::move(v));
    last = &f;
  }
  virtual_rgb_.assign(std::size_t(store_.size()), {});
  virtual_valid_.assign(std::size_t(store_.size()), {});
}

void IlluminationMap::RenderLighting() {
  std::vector<views::ReferenceView> refs;
  std::vector<Eigen::Isometry3d> poses;
  refs.reserve(frames_.size());
  for (const core::Frame& f : frames_) {
    refs.push_back(views::ReferenceViewOf(f));
    poses.push_back(*f.T_world_cam);
  }
  views::DepthMeshWarper warper(options_.synthesis.warp,
                                views::WarpOutputsFor(options_.synthesis.blend));
  for (int v = 0; v < store_.size(); ++v) {
    const views::ViewSelection sel =
        views::SelectViewsForRays(poses, store_.camera(v), store_.pose(v), options_.selection);
    cv::Mat rgb, valid;
    if (!sel.views.empty()) {
      std::vector<const views::ReferenceView*> chosen;
      for (int i : sel.views) chosen.push_back(&refs[std::size_t(i)]);
      const views::SynthesisResult r =
          views::SynthesiseView(warper, chosen, {}, sel.Weights(options_.selection),
                                store_.camera(v), store_.pose(v), options_.synthesis);
      rgb = r.rgb;
      valid = r.valid;
    } else {
      rgb = cv::Mat::zeros(store_.view(v).depth.size(), CV_8UC3);
      valid = cv::Mat::zeros(rgb.size(), CV_8UC1);
    }
    virtual_rgb_[std::size_t(v)].push_back(rgb);
    virtual_valid_[std::size_t(v)].push_back(valid);
  }
  frames_.clear();
}

void IlluminationMap::Build() {
  if (built_) throw std::logic_error("IlluminationMap: Build called twice");
  if (!frames_.empty()) {
    if (lightings_ == 1) PlaceViewpoints();
    RenderLighting();
  } else if (lightings_ > 0) {
    --lightings_;  // BeginLighting was called for a lighting that got no frames
  }
  if (lightings_ < 2)
    throw std::invalid_argument("IlluminationMap: " + std::to_string(lightings_) +
                                " lighting(s); the median of one lighting is that image's "
                                "gradient, not an invariant one — acquire at least two");
  views::ReferenceViewStore kept;
  std::string first_error;
  for (int v = 0; v < store_.size(); ++v) {
    views::ReferenceView view = store_.Decoded(v);
    try {
      const InvariantImage inv = ComputeInvariantImage(
          virtual_rgb_[std::size_t(v)], virtual_valid_[std::size_t(v)], options_.invariant);
      const double coverage = cv::countNonZero(inv.covered) / double(inv.covered.total());
      if (coverage < options_.min_viewpoint_coverage || coverage == 0.0) {
        ++dropped_;
        continue;
      }
      IlluminationViewpointModel m;
      m.model = LearnIlluminationModel(inv, virtual_valid_[std::size_t(v)], options_.model);
      m.coverage = coverage;
      view.planes[kInvariantPlane] = InvariantPlane(inv);
      view.planes[kShapesPlane] = ShapesPlane(m.model.shapes);
      m.model.shapes.clear();
      kept.Add(std::move(view));
      models_.push_back(std::move(m));
    } catch (const std::invalid_argument& e) {
      if (first_error.empty()) first_error = "viewpoint " + std::to_string(v) + ": " + e.what();
      ++dropped_;
    }
  }
  virtual_rgb_.clear();
  virtual_valid_.clear();
  store_ = std::move(kept);
  if (store_.size() == 0)
    throw std::invalid_argument("IlluminationMap: no viewpoint has an invariant image (" +
                                std::to_string(dropped_) + " dropped" +
                                (first_error.empty() ? "" : "; first: " + first_error) + ")");
  built_ = true;
}

void IlluminationMap::AddViewpoint(views::ReferenceView view, IlluminationViewpointModel model,
                                   int lightings) {
  view.Check("illumination viewpoint " + std::to_string(store_.size()));
  const auto inv = view.planes.find(kInvariantPlane);
  const auto shapes = view.planes.find(kShapesPlane);
  if (inv == view.planes.end() || shapes == view.planes.end() || inv->second.depth() != CV_32F ||
      shapes->second.depth() != CV_8U || shapes->second.channels() != lightings ||
      !(inv->second.channels() == 2 || inv->second.channels() == 4))
    throw std::invalid_argument("illumination viewpoint " + std::to_string(store_.size()) +
                                ": needs planes 'invariant' (float, 2 or 4 channels) and "
                                "'shapes' (8-bit, one channel per lighting)");
  if (!(model.model.luminance.alpha > 0.0 && model.model.luminance.beta > 0.0))
    throw std::invalid_argument("illumination viewpoint " + std::to_string(store_.size()) +
                                ": no luminance gamma model");
  if (lightings_ != 0 && lightings != lightings_)
    throw std::invalid_argument("illumination viewpoint " + std::to_string(store_.size()) + ": " +
                                std::to_string(lightings) + " lightings, the map " +
                                std::to_string(lightings_));
  lightings_ = lightings;
  store_.Add(std::move(view));
  models_.push_back(std::move(model));
  built_ = true;
}

IlluminationMapResult IlluminationMap::Detect(const core::Frame& frame) const {
  if (!built_) throw std::logic_error("IlluminationMap: Detect before Build");
  if (!frame.T_world_cam)
    throw std::invalid_argument("IlluminationMap: " + FrameName(frame) + " has no pose");
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
  std::vector<cv::Mat> invariant_planes, shape_planes;
  std::vector<const IlluminationModel*> models;
  for (int i : sel.views) {
    const views::ReferenceView& v = store_.view(i);
    sources.push_back({&v.camera, &v.T_world_cam, &v.depth, nullptr});
    invariant_planes.push_back(v.planes.at(kInvariantPlane));
    shape_planes.push_back(v.planes.at(kShapesPlane));
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
  channels.pop_back();
  cv::Mat log_invariant;
  cv::merge(channels, log_invariant);
  log_invariant.setTo(cv::Scalar::all(0), ~covered);
  out.coverage = cv::countNonZero(covered) / double(covered.total());

  IlluminationModel model = MeanModel(models, weights);
  std::vector<cv::Mat> shapes;
  cv::split(shp.value, shapes);
  for (cv::Mat& s : shapes) s = (s >= 127.5f) & covered;
  model.shapes = std::move(shapes);
  InvariantImage interpolated;
  interpolated.log_invariant = log_invariant;
  interpolated.covered = covered;
  out.viewpoint =
      MakeViewpoint(interpolated, std::move(model), options_.novelty.min_region_pixels, &zernike_);
  if (out.coverage > 0.0)
    out.novelty = DetectIlluminationNovelty(frame.rgb, out.viewpoint, zernike_, options_.novelty);
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
