#include "maps/appearance/appearance_map.h"
#include "maps/appearance/warp_error_floor.h"
#include "maps/views/plane_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

#include "core/depth_check.h"
#include "core/fill_where.h"
#include "core/interleave.h"
#include "core/rigid_pose.h"
#include "maps/color/ycbcr_planes.h"
#include "maps/stats/predictive_novelty.h"

namespace novelty::appearance {

void CheckFrame(const cv::Mat& rgb, const cv::Mat& depth, const core::PinholeCamera& camera,
                const Eigen::Isometry3d& T_world_cam, const char* what) {
  camera.Check();
  const cv::Size size(camera.width, camera.height);
  if (rgb.type() != CV_8UC3 || rgb.size() != size) {
    throw std::invalid_argument(std::string(what) + ": image must be CV_8UC3 of " +
                                std::to_string(size.width) + "x" + std::to_string(size.height));
  }
  if (depth.type() != CV_32FC1 || depth.size() != size) {
    throw std::invalid_argument(std::string(what) + ": depth must be CV_32FC1 of " +
                                std::to_string(size.width) + "x" + std::to_string(size.height));
  }
  if (!core::IsRigid(T_world_cam)) {
    throw std::invalid_argument(std::string(what) + ": pose is not a rigid transform");
  }
  if (const int bad = core::CountBrokenDepths(depth); bad > 0) {
    throw std::invalid_argument(std::string(what) + ": " + std::to_string(bad) +
                                " depths are negative or infinite");
  }
}

namespace {

constexpr int kChannels = AppearanceMap::kChannels, kAlpha = AppearanceMap::kAlpha,
              kBeta = AppearanceMap::kBeta, kTau = AppearanceMap::kTau,
              kSigma = AppearanceMap::kSigma;

// A frame is processed in tiles of this many rows, on all cores: each tile's working planes
// (about 30 of 320 floats per row) stay in cache from the blend of its prior and the colour
// conversion through the kernel to the stored posterior. The threads take one tile at a time:
// tiles differ in cost with the views covering them, and single tiles keep both cores busy to
// the end, which one stripe of tiles per thread does not (appearance_map_benchmark;
// docs/performance_history.md).
constexpr int kTileRows = 8;

// One frame: what every tile reads, and the new images (handed out, or kept by the store) that
// each tile writes its rows of.
struct FrameRows {
  const cv::Mat& rgb;
  const cv::Mat& depth;
  const Prediction& prior;               // its rows hold nothing until blended (BlendRows)
  std::array<float, kChannels> initial;  // the initial prior, in Channel order
  double warp_sigma_px;                  // 0 unless the prior was warped (warp_error_floor.h)
  double hold_above_nats;                // AppearanceMapOptions::hold_above_nats
  cv::Mat observed_y;  // learn_warp_sigma: the tiles leave their rows of the frame's Y here
  cv::Mat surprise, expected_rgb, uncertainty, stored_ab_sigma, stored_tau, stored_depth,
      predictive;
  int max_hold_frames;  // AppearanceMapOptions::max_hold_frames
  cv::Mat held_frames;  // CV_16UC1, per pixel the frames it has been held in a row (kept)
};

// Working planes of one tile, reused for the tiles one task processes; prior and posterior
// planes in the stored images' channel order.
struct TileWork {
  std::vector<cv::Mat> x, ab_sigma, tau, post_ab_sigma, post_tau;
  cv::Mat uncovered;
  stats::ChannelPlanes channels;
  cv::Mat log_u, log_v, offset;  // predictive novelty's logarithms (PredictiveRows)
};

// The parameter planes of one tile in Channel order.
std::array<cv::Mat*, kChannels> InChannelOrder(std::vector<cv::Mat>& ab_sigma,
                                               std::vector<cv::Mat>& tau) {
  return {&ab_sigma[0], &ab_sigma[1], &ab_sigma[2], &ab_sigma[3], &tau[0],
          &tau[1],      &tau[2],      &ab_sigma[4], &ab_sigma[5], &ab_sigma[6]};
}

// Rows [r.start, r.end) of `m` as a header that does not share m's reference count: the tiles of
// both threads would otherwise count up and down on the same frame images' counters.
cv::Mat RowsOf(const cv::Mat& m, const cv::Range& r) {
  return cv::Mat(r.size(), m.cols, m.type(), const_cast<uchar*>(m.ptr(r.start)), m.step[0]);
}

// Predictive novelty of a tile (stats/predictive_novelty.h): the two logarithms' arguments a
// pixel at a time, the logarithms a plane at a time (OpenCV's vectorised cv::log).
void PredictiveRows(const std::array<cv::Mat*, kChannels>& p0, const std::vector<cv::Mat>& x,
                    TileWork& t, cv::Mat& out) {
  const std::size_t n = out.total();
  for (cv::Mat* m : {&t.log_u, &t.log_v, &t.offset}) m->create(out.size(), CV_32FC1);
  float *u = t.log_u.ptr<float>(), *v = t.log_v.ptr<float>(), *o = t.offset.ptr<float>();
  const float* alpha = p0[kAlpha]->ptr<float>();
  const float *b0 = p0[kBeta]->ptr<float>(), *b1 = p0[kBeta + 1]->ptr<float>(),
              *b2 = p0[kBeta + 2]->ptr<float>();
  const float *t0 = p0[kTau]->ptr<float>(), *t1 = p0[kTau + 1]->ptr<float>(),
              *t2 = p0[kTau + 2]->ptr<float>();
  const float *s0 = p0[kSigma]->ptr<float>(), *s1 = p0[kSigma + 1]->ptr<float>(),
              *s2 = p0[kSigma + 2]->ptr<float>();
  const float *x0 = x[0].ptr<float>(), *x1 = x[1].ptr<float>(), *x2 = x[2].ptr<float>();
  // Sixteen pixels at a time as Eigen arrays: GCC leaves the loop over floats scalar (the
  // template's arrays of structs), which cost as much as the whole surprise kernel.
  const auto arguments = [&](auto of, std::size_t i) {
    using T = decltype(of(alpha, i));
    const T a = of(alpha, i);
    const stats::NormalGammaT<T> p[3] = {{a, of(b0, i), of(t0, i), of(s0, i)},
                                         {a, of(b1, i), of(t1, i), of(s1, i)},
                                         {a, of(b2, i), of(t2, i), of(s2, i)}};
    const T xs[3] = {of(x0, i), of(x1, i), of(x2, i)};
    T uu, vv, oo;
    stats::PredictiveLogArguments(p, xs, 3, uu, vv, oo);
    return std::array<T, 3>{uu, vv, oo};
  };
  using Packet = Eigen::Array<float, 16, 1>;
  std::size_t i = 0;
  for (; i + Packet::SizeAtCompileTime <= n; i += Packet::SizeAtCompileTime) {
    const auto r =
        arguments([](const float* p, std::size_t k) { return Packet(Packet::Map(p + k)); }, i);
    Packet::Map(u + i) = r[0], Packet::Map(v + i) = r[1], Packet::Map(o + i) = r[2];
  }
  for (; i < n; ++i) {
    const auto r = arguments([](const float* p, std::size_t k) { return p[k]; }, i);
    u[i] = r[0], v[i] = r[1], o[i] = r[2];
  }
  cv::log(t.log_u, t.log_u);
  cv::log(t.log_v, t.log_v);
  float* result = out.ptr<float>();
  for (std::size_t k = 0; k < n; ++k) result[k] = 0.5f * u[k] + (alpha[k] + 0.5f) * v[k] + o[k];
}

// The hold rule on a tile's rows (AppearanceMapOptions::hold_above_nats, max_hold_frames): where
// predictive novelty exceeds the threshold the posterior is the prior, unless the pixel has been
// held max_hold_frames in a row. One pass that touches the parameters of held pixels only (the
// few), where masked copies of ten planes cost as much as the predictive product itself.
void HoldRows(const cv::Mat& predictive, const FrameRows& f, cv::Mat held,
              const std::array<cv::Mat*, kChannels>& p0,
              const std::array<cv::Mat*, kChannels>& p1) {
  CV_Assert(predictive.isContinuous() && (held.empty() || held.isContinuous()));
  std::array<const float*, kChannels> from;
  std::array<float*, kChannels> to;
  for (int c = 0; c < kChannels; ++c) {
    CV_Assert(p0[c]->isContinuous() && p1[c]->isContinuous());
    from[c] = p0[c]->ptr<float>(), to[c] = p1[c]->ptr<float>();
  }
  const float threshold = float(f.hold_above_nats), *q = predictive.ptr<float>();
  std::uint16_t* count = held.empty() ? nullptr : held.ptr<std::uint16_t>();
  for (std::size_t i = 0, n = predictive.total(); i < n; ++i) {
    if (!(q[i] > threshold)) {  // NaN (uncovered) is not held
      if (count) count[i] = 0;
      continue;
    }
    if (count) {
      count[i] = std::uint16_t(std::min(int(count[i]) + 1, 65535));
      if (count[i] > f.max_hold_frames) continue;  // held that long: it learns again
    }
    for (int c = 0; c < kChannels; ++c) to[c][i] = from[c][i];
  }
}

// Rows [r0, r1): prior planes from the prediction, update and surprise (eq. 4.8-4.21; α is shared
// by the three channels), and the rows of every product and of the posterior to be stored.
void ProcessRows(const FrameRows& f, const stats::SurpriseBatchOptions& options, int r0, int r1,
                 TileWork& t) {
  const cv::Range rows(r0, r1);
  f.prior.BlendRows(rows);
  const cv::Mat valid = RowsOf(f.prior.valid, rows);
  cv::Mat uncovered;  // empty where the map covers every pixel of the tile
  if (cv::countNonZero(valid) < int(valid.total())) {
    cv::compare(valid, 0, t.uncovered, cv::CMP_EQ);
    uncovered = t.uncovered;
  }
  color::RgbToYCbCrPlanes(RowsOf(f.rgb, rows), t.x);
  if (!f.observed_y.empty()) {
    cv::Mat observed_y = RowsOf(f.observed_y, rows);  // written in place
    t.x[0].copyTo(observed_y);
  }
  // Half floats (a static camera reads its view's stored planes in place) or blended floats.
  core::SplitToFloat(RowsOf(f.prior.value[0], rows), t.ab_sigma);
  core::SplitToFloat(RowsOf(f.prior.value[1], rows), t.tau);
  const std::array<cv::Mat*, kChannels> p0 = InChannelOrder(t.ab_sigma, t.tau);
  if (!uncovered.empty()) {  // the initial prior where no view covers (a static camera: never)
    for (int c = 0; c < kChannels; ++c)
      core::FillWhere(*p0[c], uncovered, f.initial[std::size_t(c)]);
  }
  FloorVarianceByWarpError(f.prior.value[1], rows, f.warp_sigma_px, *p0[kAlpha],
                           {p0[kBeta], p0[kBeta + 1], p0[kBeta + 2]});
  t.post_ab_sigma.resize(t.ab_sigma.size());
  t.post_tau.resize(t.tau.size());
  for (auto* planes : {&t.post_ab_sigma, &t.post_tau})
    for (cv::Mat& m : *planes) m.create(r1 - r0, f.rgb.cols, CV_32FC1);
  const std::array<cv::Mat*, kChannels> p1 = InChannelOrder(t.post_ab_sigma, t.post_tau);
  stats::ChannelPlanes& channels = t.channels;  // refilled: its vectors keep their capacity
  channels.x.clear();
  channels.prior.clear();
  channels.posterior.clear();
  for (int k = 0; k < 3; ++k) {
    channels.x.push_back(t.x[k].ptr<float>());
    channels.prior.push_back({p0[kAlpha]->ptr<float>(), p0[kBeta + k]->ptr<float>(),
                              p0[kTau + k]->ptr<float>(), p0[kSigma + k]->ptr<float>()});
    channels.posterior.push_back({p1[kAlpha]->ptr<float>(), p1[kBeta + k]->ptr<float>(),
                                  p1[kTau + k]->ptr<float>(), p1[kSigma + k]->ptr<float>()});
  }
  cv::Mat surprise = RowsOf(f.surprise, rows);
  surprise.setTo(0.0f);
  stats::UpdateAndAccumulateSurprise(channels, surprise.ptr<float>(), surprise.total(), options);
  cv::Mat predictive;
  if (!f.predictive.empty()) {
    predictive = RowsOf(f.predictive, rows);
    PredictiveRows(p0, t.x, t, predictive);
  }

  // Products: the prior's τ in RGB, its Σβ; NaN or black where not covered.
  cv::Mat expected_rgb = RowsOf(f.expected_rgb, rows), uncertainty = RowsOf(f.uncertainty, rows);
  color::YCbCrPlanesToRgb(*p0[kTau], *p0[kTau + 1], *p0[kTau + 2], expected_rgb);
  cv::add(*p0[kBeta], *p0[kBeta + 1], uncertainty);
  cv::add(uncertainty, *p0[kBeta + 2], uncertainty);
  if (!uncovered.empty()) {
    core::FillWhere(surprise, uncovered, std::numeric_limits<float>::quiet_NaN());
    core::FillWhere(expected_rgb, uncovered, cv::Scalar::all(0));
    core::FillWhere(uncertainty, uncovered, std::numeric_limits<float>::quiet_NaN());
    if (!predictive.empty())
      core::FillWhere(predictive, uncovered, std::numeric_limits<float>::quiet_NaN());
  }
  // Where the frame is foreground by the hold rule, the prior stays (AppearanceMapOptions).
  if (!predictive.empty() && std::isfinite(f.hold_above_nats))
    HoldRows(predictive, f, f.max_hold_frames > 0 ? RowsOf(f.held_frames, rows) : cv::Mat(), p0,
             p1);
  // The posterior as the store keeps it.
  cv::Mat stored_ab_sigma = RowsOf(f.stored_ab_sigma, rows);
  core::MergeInto(t.post_ab_sigma, stored_ab_sigma);
  cv::Mat stored_tau = RowsOf(f.stored_tau, rows);
  core::MergeInto(t.post_tau, stored_tau);
  cv::Mat stored_depth = RowsOf(f.stored_depth, rows);  // the store keeps a copy: in parallel
  RowsOf(f.depth, rows).copyTo(stored_depth);
}

}  // namespace

// Working planes for the tiles in progress, one set per thread at a time, kept between tiles and
// frames so that a frame allocates none.
struct AppearanceMap::TileWorkPool {
  std::mutex mutex;
  std::vector<std::unique_ptr<TileWork>> free;

  std::unique_ptr<TileWork> Take() {
    const std::lock_guard<std::mutex> lock(mutex);
    if (free.empty()) return std::make_unique<TileWork>();
    std::unique_ptr<TileWork> t = std::move(free.back());
    free.pop_back();
    return t;
  }
  void Give(std::unique_ptr<TileWork> t) {
    const std::lock_guard<std::mutex> lock(mutex);
    free.push_back(std::move(t));
  }
};

AppearanceMap::~AppearanceMap() = default;

cv::Mat AppearanceMap::HeldFrames(int rows, int cols) {
  if (options_.max_hold_frames <= 0) return {};
  if (held_frames_.rows != rows || held_frames_.cols != cols)
    held_frames_ = cv::Mat::zeros(rows, cols, CV_16UC1);
  return held_frames_;
}

AppearanceMap::AppearanceMap(const AppearanceMapOptions& options)
    : options_(options), map_(options.views), tile_work_(std::make_unique<TileWorkPool>()) {
  options_.surprise.update.Check();
  if (options_.max_hold_frames < 0 || options_.max_hold_frames > 65000)
    throw std::invalid_argument("AppearanceMapOptions: max_hold_frames must be in 0…65000");
  if (!(options_.hold_above_nats > 0.0) ||
      (std::isfinite(options_.hold_above_nats) && !options_.predictive_novelty))
    throw std::invalid_argument(
        "AppearanceMapOptions: hold_above_nats must be > 0, and finite only with "
        "predictive_novelty");
  if (!(std::isfinite(options_.warp_sigma_px) && options_.warp_sigma_px >= 0.0)) {
    throw std::invalid_argument(
        "AppearanceMapOptions: warp_sigma_px must be finite and >= 0, got " +
        std::to_string(options_.warp_sigma_px));
  }
  stats::CheckNormalGamma(options_.initial_prior, "AppearanceMapOptions::initial_prior");
}

void AppearanceMap::CheckStoredPlanes() const {
  views::CheckPlanes(map_.store(), {{"ab_sigma", 7, views::PlaneValues::kPositive},
                                    {"tau", 3, views::PlaneValues::kFinite}});
}

void AppearanceMap::LearnWarpSigma(const cv::Mat& observed_y, const cv::Mat& tau) {
  const double s = MeasureWarpSigma(observed_y, tau);
  if (std::isnan(s)) return;  // too few edges to tell
  const double f = options_.surprise.update.forgetting_factor;
  learnt_warp_variance_ = f * learnt_warp_variance_ + (1.0 - f) * s * s;
}

AppearanceProducts AppearanceMap::Insert(const cv::Mat& rgb, const cv::Mat& depth,
                                         const core::PinholeCamera& camera,
                                         const Eigen::Isometry3d& T_world_cam) {
  CheckFrame(rgb, depth, camera, T_world_cam, "AppearanceMap::Insert");
  const int rows = camera.height, cols = camera.width;
  // Prior: blended reference parameters, each tile's rows by the tile; the initial prior where no
  // view covers.
  // The warp-error floor differentiates τ across tile borders: it needs the whole prior blended
  // first (a pass more over the frame); without it each tile blends its own rows.
  const std::vector<std::pair<std::string, int>> planes = {{"ab_sigma", 7}, {"tau", 3}};
  const bool floor = options_.warp_sigma_px > 0.0 || options_.learn_warp_sigma;
  const bool whole = floor || options_.align_to_prior;
  Eigen::Isometry3d pose = T_world_cam;
  Prediction prior = whole ? map_.Predict(camera, pose, planes, predict_depth_)
                           : map_.PredictDeferred(camera, pose, planes, predict_depth_);
  Eigen::Vector3d aligned_rotation = Eigen::Vector3d::Zero();
  if (options_.align_to_prior && prior.warped) {
    std::vector<cv::Mat> ycbcr, tau;
    color::RgbToYCbCrPlanes(rgb, ycbcr);
    cv::split(prior.value[1], tau);
    const PriorAlignment a = AlignRotationToPrior(ycbcr[0], tau[0], camera, options_.alignment);
    if (a.aligned) {
      aligned_rotation = a.rotation;
      pose = T_world_cam * Eigen::Isometry3d(RotationFromVector(a.rotation));
      prior = map_.Predict(camera, pose, planes, predict_depth_);
    }
  }
  const bool learn = options_.learn_warp_sigma && prior.warped && map_.learning();
  const double warp_sigma =
      prior.warped ? std::max(options_.warp_sigma_px, std::sqrt(learnt_warp_variance_)) : 0.0;
  const stats::NormalGamma& init = options_.initial_prior;
  const float alpha0 = float(init.alpha), beta0 = float(init.beta), tau0 = float(init.tau),
              sigma0 = float(init.sigma);
  const FrameRows f{rgb,
                    depth,
                    prior,
                    {alpha0, beta0, beta0, beta0, tau0, tau0, tau0, sigma0, sigma0, sigma0},
                    warp_sigma,
                    options_.hold_above_nats,
                    learn ? cv::Mat(rows, cols, CV_32FC1) : cv::Mat(),
                    cv::Mat(rows, cols, CV_32FC1),
                    cv::Mat(rows, cols, CV_8UC3),
                    cv::Mat(rows, cols, CV_32FC1),
                    cv::Mat(rows, cols, CV_MAKETYPE(options_.half_precision ? CV_16F : CV_32F, 7)),
                    cv::Mat(rows, cols, CV_32FC3),
                    cv::Mat(rows, cols, CV_32FC1),
                    options_.predictive_novelty ? cv::Mat(rows, cols, CV_32FC1) : cv::Mat(),
                    options_.max_hold_frames,
                    HeldFrames(rows, cols)};
  const int tiles = (rows + kTileRows - 1) / kTileRows;
  // Beside the tiles, when the frame was warped, one more task: the mesh plan of the frame's
  // depth, which the view the frame becomes keeps for its next warp — a moving camera warps it
  // next frame (a static camera never does, and is not charged for it).
  const int plan_tasks = prior.warped && map_.learning() ? 1 : 0;
  views::MeshPlan plan;
  cv::parallel_for_(
      cv::Range(0, plan_tasks + tiles),
      [&](const cv::Range& r) {
        std::unique_ptr<TileWork> t = tile_work_->Take();
        for (int i = r.start; i < r.end; ++i) {
          if (i < plan_tasks) {
            plan = map_.PlanMesh(depth);
            continue;
          }
          const int r0 = (i - plan_tasks) * kTileRows;
          ProcessRows(f, options_.surprise, r0, std::min(rows, r0 + kTileRows), *t);
        }
        tile_work_->Give(std::move(t));  // (not after an exception: the pool makes another)
      },
      plan_tasks + tiles);

  AppearanceProducts out;
  out.valid = prior.valid;
  // A static camera's prediction shares the view's depth, which the update below replaces.
  out.expected_depth = prior.warped ? prior.depth : prior.depth.clone();
  out.expected_depth_span = prior.depth_span;  // its own buffer, even for a static camera
  out.warp_sigma_px = warp_sigma;
  out.aligned_rotation = aligned_rotation;
  out.T_world_cam = pose;
  out.selected = prior.selected;
  out.surprise = f.surprise;
  out.expected_rgb = f.expected_rgb;
  out.uncertainty = f.uncertainty;
  out.predictive = f.predictive;
  // What this frame teaches of s serves the next frame's floor, never its own.
  if (learn) LearnWarpSigma(f.observed_y, prior.value[1]);
  // The posterior at this viewpoint goes into the map (4.3's update policy).
  // The view keeps the pose the caller gave (align_to_prior): a view at the aligned pose would
  // chain each frame to the last one's correction, and the alignments' own errors would add up
  // (0.16° within seven frames of the table clip at true poses). At the given pose a view
  // carries the pose source's error of its own frame; a later frame's alignment measures its
  // error relative to the views its prior comes from (one view for most frames, 3.3.1), not the
  // absolute one.
  out.update = map_.Update(camera, T_world_cam, f.stored_depth,
                           {{"ab_sigma", f.stored_ab_sigma}, {"tau", f.stored_tau}}, prior.selected,
                           std::move(plan));
  return out;
}

}  // namespace novelty::appearance
