#include "maps/illumination/illumination_model.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "maps/color/hsv.h"
#include "maps/illumination/invariant_image.h"
#include "maps/stats/special_functions.h"

namespace novelty::illumination {

namespace {

cv::Mat Valid(const InvariantImage& invariant, const std::vector<cv::Mat>& coverage,
              std::size_t m) {
  cv::Mat valid = invariant.covered.clone();
  if (!coverage.empty()) valid &= coverage[m];
  return valid;
}

// The valid values, no smaller than half their quantisation width.
void AppendSamples(const cv::Mat& values, const cv::Mat& valid, double step,
                   std::vector<double>& samples) {
  for (int y = 0; y < values.rows; ++y) {
    const float* v = values.ptr<float>(y);
    const uchar* ok = valid.ptr<uchar>(y);
    for (int x = 0; x < values.cols; ++x)
      if (ok[x]) samples.push_back(std::max<double>(v[x], 0.5 * step));
  }
}

// The mean of Σ|∇r̂|² / N over the covered pixels: the floor of HiddenTextureShare, so that
// only texture stronger than the viewpoint's average can be hidden in full.
double TextureFloor(const InvariantImage& invariant, const MissingTextureOptions& options) {
  const double mean = cv::mean(GradientEnergy(invariant.log_invariant, invariant.covered, options),
                               invariant.covered)[0];
  return std::max(mean, 1e-12);
}

// The missing texture's scale and training sample. Per pixel the scale is the largest share of
// texture any training image hides or adds there (at a fold or an object's outline lighting
// changes the contrast either way), plus the mean over all pixels and images: a floor, so that on
// flat surfaces, where lighting changes no texture, the share is not divided by 0. Each training
// image's u is taken against the largest of the *other* images (leave one out): a new frame is
// not part of the maximum it is compared with, and a sample measured against its own maximum
// would never exceed 1 — every new frame's noise above it would look as rare as can be.
struct TextureStatistics {
  cv::Mat scale;
  std::vector<float> samples;
};

TextureStatistics LearnTextureStatistics(const std::vector<cv::Mat>& hidden,
                                         const std::vector<cv::Mat>& valid) {
  const cv::Size size = hidden.front().size();
  cv::Mat first = cv::Mat::zeros(size, CV_32F), second = first.clone();
  double sum = 0.0, count = 0.0;
  for (std::size_t m = 0; m < hidden.size(); ++m)
    for (int y = 0; y < size.height; ++y)
      for (int x = 0; x < size.width; ++x) {
        if (!valid[m].at<uchar>(y, x)) continue;
        const float h = std::abs(hidden[m].at<float>(y, x));
        float &a = first.at<float>(y, x), &b = second.at<float>(y, x);
        if (h >= a)
          b = a, a = h;
        else if (h > b)
          b = h;
        sum += h, count += 1.0;
      }
  const float floor = float((count > 0.0 ? sum / count : 0.0) + 1e-6);
  TextureStatistics out;
  out.scale = first + floor;
  for (std::size_t m = 0; m < hidden.size(); ++m)
    for (int y = 0; y < size.height; ++y)
      for (int x = 0; x < size.width; ++x) {
        if (!valid[m].at<uchar>(y, x)) continue;
        const float h = hidden[m].at<float>(y, x), a = first.at<float>(y, x);
        const float others = std::abs(h) >= a ? second.at<float>(y, x) : a;
        out.samples.push_back(std::max(h, 0.0f) / (others + floor));
      }
  return out;
}

}  // namespace

IlluminationComponents ComputeIlluminationComponents(const cv::Mat& log_illumination) {
  if (log_illumination.empty() || log_illumination.depth() != CV_32F ||
      (log_illumination.channels() != 1 && log_illumination.channels() != 3))
    throw std::invalid_argument(
        "ComputeIlluminationComponents: a CV_32FC1 or CV_32FC3 log illumination image is needed");
  IlluminationComponents out;
  const cv::Mat lighting = LinearImage(log_illumination);
  if (lighting.channels() == 3) {
    std::vector<cv::Mat> hsv;
    cv::split(color::RgbToHsv(lighting), hsv);
    out.luminance = hsv[2];
    out.saturation = hsv[1];
  } else {
    out.luminance = lighting;
  }
  return out;
}

cv::Mat InformationMap(const cv::Mat& values, double step, const stats::GammaFit& fit) {
  if (values.type() != CV_32FC1 || !(step > 0.0))
    throw std::invalid_argument("InformationMap: CV_32FC1 values and a width > 0 are needed");
  if (!(fit.alpha > 0.0 && fit.beta > 0.0))
    throw std::invalid_argument("InformationMap: the gamma fit has no positive α and β");
  // log p(x) = a log b - log Γ(a) + (a - 1) log x - b x   (eq. 6.16)
  const double a = fit.alpha, b = fit.beta;
  const double constant = a * std::log(b) - stats::LogGamma(a) + std::log(step);
  cv::Mat info(values.size(), CV_32F);
  for (int y = 0; y < values.rows; ++y) {
    const float* v = values.ptr<float>(y);
    float* out = info.ptr<float>(y);
    for (int x = 0; x < values.cols; ++x) {
      const double value = std::max<double>(v[x], 0.5 * step);
      out[x] = float(-(constant + (a - 1.0) * std::log(value) - b * value));
    }
  }
  return info;
}

IlluminationModel LearnIlluminationModel(const InvariantImage& invariant,
                                         const std::vector<cv::Mat>& coverage,
                                         const IlluminationModelOptions& options) {
  if (!(options.kappa >= 0.0 && options.kappa < 1.0) || !(options.luminance_step > 0.0) ||
      !(options.saturation_step > 0.0))
    throw std::invalid_argument(
        "LearnIlluminationModel: kappa must be in [0, 1) and the widths > 0");
  const std::size_t m_count = invariant.log_illumination.size();
  if (!coverage.empty() && coverage.size() != m_count)
    throw std::invalid_argument("LearnIlluminationModel: " + std::to_string(coverage.size()) +
                                " coverage masks for " + std::to_string(m_count) +
                                " illumination images");
  std::vector<IlluminationComponents> components;
  std::vector<cv::Mat> valid;  // per image: covered by the invariant image and by the image
  std::vector<double> luminance, saturation;
  std::vector<cv::Mat> hidden;  // per image, with options.missing_texture
  const double texture_floor =
      options.missing_texture ? TextureFloor(invariant, options.texture) : 0.0;
  for (std::size_t m = 0; m < m_count; ++m) {
    components.push_back(ComputeIlluminationComponents(invariant.log_illumination[m]));
    valid.push_back(Valid(invariant, coverage, m));
    AppendSamples(components.back().luminance, valid[m], options.luminance_step, luminance);
    if (!components.back().saturation.empty())
      AppendSamples(components.back().saturation, valid[m], options.saturation_step, saturation);
    if (options.missing_texture)
      hidden.push_back(HiddenTextureShare(invariant.log_illumination[m] + invariant.log_invariant,
                                          invariant.log_invariant, valid[m], texture_floor,
                                          options.texture));
  }
  if (luminance.empty()) throw std::invalid_argument("LearnIlluminationModel: no pixel is covered");
  IlluminationModel model;
  model.luminance_step = options.luminance_step;
  model.saturation_step = options.saturation_step;
  model.luminance = stats::FitGammaML(luminance);
  if (model.luminance.status == stats::GammaFit::Status::kConstant)
    throw std::invalid_argument(
        "LearnIlluminationModel: the illumination images do not vary — the lightings are "
        "identical, so nothing about lighting can be learnt");
  // A scene without colour (grey images, or all saturation below one level) has no saturation
  // model: its information is 0.
  if (!saturation.empty()) {
    const stats::GammaFit s = stats::FitGammaML(saturation);
    if (s.status != stats::GammaFit::Status::kConstant) model.saturation = s;
  }
  if (options.missing_texture) {
    TextureStatistics statistics = LearnTextureStatistics(hidden, valid);
    model.texture = stats::LearnTail(statistics.samples);
    model.texture_block = options.texture.block;
    model.texture_floor = texture_floor;
    model.texture_scale = statistics.scale;
  }
  std::vector<cv::Mat> information;
  double sum = 0.0, count = 0.0;
  for (std::size_t m = 0; m < m_count; ++m) {
    information.push_back(
        InformationMap(components[m].luminance, model.luminance_step, model.luminance));
    const int n = cv::countNonZero(valid[m]);
    if (n > 0) sum += cv::mean(information.back(), valid[m])[0] * n;
    count += n;
  }
  model.mean_information = sum / count;
  if (!(model.mean_information > 0.0))
    throw std::invalid_argument(
        "LearnIlluminationModel: the illumination varies by less than one quantisation level "
        "(mean information " +
        std::to_string(model.mean_information) + "): T_Y of eq. 6.18 would not be positive");
  model.threshold = model.mean_information / (1.0 - options.kappa);  // eq. 6.18
  for (std::size_t m = 0; m < m_count; ++m)
    model.shapes.push_back((information[m] > model.threshold) & valid[m]);
  return model;
}

}  // namespace novelty::illumination
