#include "maps/appearance/appearance_map.h"

#include <limits>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

#include "maps/color/ycbcr.h"

namespace novelty::appearance {

void CheckFrame(const cv::Mat& rgb, const cv::Mat& depth, const views::PinholeCamera& camera,
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
  if (!views::IsRigid(T_world_cam)) {
    throw std::invalid_argument(std::string(what) + ": pose is not a rigid transform");
  }
}

struct AppearanceMap::Workspace {
  cv::Mat ycbcr, expected;  // CV_32FC3: the frame in YCbCr; the prior's τ in RGB
  std::vector<cv::Mat> x;   // Y, Cb, Cr planes
  ViewBasedMap::Prediction prior;
  std::vector<cv::Mat> ab_sigma, tau;  // the prior's planes (α, β×3, σ×3; τ×3)
  std::vector<cv::Mat> posterior;      // kChannels planes
  // Interleaved images before conversion: τ (3 channels) and α, β, σ (7); one buffer each, since
  // a buffer of the other channel count would be reallocated twice a frame.
  cv::Mat merged_tau, merged_ab_sigma;
};

AppearanceMap::~AppearanceMap() = default;

AppearanceMap::AppearanceMap(const AppearanceMapOptions& options)
    : options_(options), map_(options.views), work_(std::make_unique<Workspace>()) {
  options_.surprise.update.Check();
  stats::CheckNormalGamma(options_.initial_prior, "AppearanceMapOptions::initial_prior");
}

AppearanceProducts AppearanceMap::Insert(const cv::Mat& rgb, const cv::Mat& depth,
                                         const views::PinholeCamera& camera,
                                         const Eigen::Isometry3d& T_world_cam) {
  CheckFrame(rgb, depth, camera, T_world_cam, "AppearanceMap::Insert");
  const int n = camera.width * camera.height;
  Workspace& w = *work_;
  color::RgbToYCbCr(rgb, w.ycbcr);
  cv::split(w.ycbcr, w.x);

  // Prior: blended reference parameters; the initial prior where no view covers.
  ViewBasedMap::Prediction& prior = w.prior;
  map_.Predict(camera, T_world_cam, {{"ab_sigma", 7}, {"tau", 3}}, prior);
  cv::split(prior.value[0], w.ab_sigma);
  cv::split(prior.value[1], w.tau);
  std::vector<cv::Mat> p0(kChannels);
  p0[kAlpha] = w.ab_sigma[0];
  for (int k = 0; k < 3; ++k) {
    p0[kBeta + k] = w.ab_sigma[1 + k];
    p0[kSigma + k] = w.ab_sigma[4 + k];
    p0[kTau + k] = w.tau[k];
  }
  const stats::NormalGamma& init = options_.initial_prior;
  const float initial[kChannels] = {
      float(init.alpha), float(init.beta), float(init.beta),  float(init.beta),  float(init.tau),
      float(init.tau),   float(init.tau),  float(init.sigma), float(init.sigma), float(init.sigma)};
  // Masked writes only where the map has gaps (a static camera has none: 13 passes saved).
  const bool gaps = cv::countNonZero(prior.valid) < n;
  const cv::Mat uncovered = gaps ? cv::Mat(~prior.valid) : cv::Mat();
  if (gaps) {
    for (int c = 0; c < kChannels; ++c) p0[c].setTo(initial[c], uncovered);
  }

  // Update and surprise per channel (eq. 4.8-4.21); α is shared by the three channels.
  std::vector<cv::Mat>& p1 = w.posterior;
  p1.resize(kChannels);
  for (cv::Mat& m : p1) m.create(camera.height, camera.width, CV_32FC1);
  cv::Mat surprise(camera.height, camera.width, CV_32FC1, cv::Scalar(0));
  stats::ChannelPlanes channels;
  for (int k = 0; k < 3; ++k) {
    channels.x.push_back(w.x[k].ptr<float>());
    channels.prior.push_back({p0[kAlpha].ptr<float>(), p0[kBeta + k].ptr<float>(),
                              p0[kTau + k].ptr<float>(), p0[kSigma + k].ptr<float>()});
    channels.posterior.push_back({p1[kAlpha].ptr<float>(), p1[kBeta + k].ptr<float>(),
                                  p1[kTau + k].ptr<float>(), p1[kSigma + k].ptr<float>()});
  }
  stats::UpdateAndAccumulateSurprise(channels, surprise.ptr<float>(), std::size_t(n),
                                     options_.surprise);

  AppearanceProducts out;
  out.valid = prior.valid;
  out.selected = prior.selected;
  out.surprise = surprise;
  if (gaps) out.surprise.setTo(std::numeric_limits<float>::quiet_NaN(), uncovered);
  cv::merge(std::vector<cv::Mat>{p0[kTau], p0[kTau + 1], p0[kTau + 2]}, w.merged_tau);
  color::YCbCrToRgb(w.merged_tau, w.expected);
  w.expected.convertTo(out.expected_rgb, CV_8UC3);
  if (gaps) out.expected_rgb.setTo(cv::Scalar::all(0), uncovered);
  out.uncertainty = p0[kBeta] + p0[kBeta + 1] + p0[kBeta + 2];
  if (gaps) out.uncertainty.setTo(std::numeric_limits<float>::quiet_NaN(), uncovered);

  // The posterior at this viewpoint goes into the map (4.3's update policy): new images, since
  // the store keeps them.
  cv::Mat ab_sigma_stored, tau1;
  cv::merge(std::vector<cv::Mat>{p1[kAlpha], p1[kBeta], p1[kBeta + 1], p1[kBeta + 2], p1[kSigma],
                                 p1[kSigma + 1], p1[kSigma + 2]},
            w.merged_ab_sigma);
  w.merged_ab_sigma.convertTo(ab_sigma_stored, options_.half_precision ? CV_16F : CV_32F);
  cv::merge(std::vector<cv::Mat>{p1[kTau], p1[kTau + 1], p1[kTau + 2]}, tau1);
  out.update = map_.Update(camera, T_world_cam, depth,
                           {{"ab_sigma", ab_sigma_stored}, {"tau", tau1}}, prior.selected);
  return out;
}

}  // namespace novelty::appearance
