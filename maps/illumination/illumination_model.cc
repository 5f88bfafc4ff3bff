#include "maps/illumination/illumination_model.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "maps/color/hsv.h"
#include "maps/stats/special_functions.h"

namespace novelty::illumination {

namespace {

// The largest channel of a float image.
cv::Mat LargestChannel(const cv::Mat& image) {
  std::vector<cv::Mat> planes;
  cv::split(image, planes);
  cv::Mat largest = planes[0].clone();
  for (std::size_t c = 1; c < planes.size(); ++c) cv::max(largest, planes[c], largest);
  return largest;
}

cv::Mat Valid(const InvariantImage& invariant, const std::vector<cv::Mat>& coverage,
              std::size_t m) {
  cv::Mat valid = invariant.covered.clone();
  if (!coverage.empty()) valid &= coverage[m];
  return valid;
}

void AppendSamples(const cv::Mat& values, const cv::Mat& valid, std::vector<double>& samples) {
  for (int y = 0; y < values.rows; ++y) {
    const float* v = values.ptr<float>(y);
    const uchar* ok = valid.ptr<uchar>(y);
    for (int x = 0; x < values.cols; ++x)
      if (ok[x]) samples.push_back(v[x]);
  }
}

}  // namespace

IlluminationComponents ComputeIlluminationComponents(const cv::Mat& log_illumination,
                                                     const cv::Mat& log_invariant,
                                                     const cv::Mat& image,
                                                     const IlluminationModelOptions& options) {
  if (log_illumination.empty() || log_illumination.size() != log_invariant.size() ||
      log_illumination.type() != log_invariant.type() || image.size() != log_invariant.size() ||
      image.channels() != log_invariant.channels())
    throw std::invalid_argument(
        "ComputeIlluminationComponents: illumination, invariant and camera image must have one "
        "size and one number of channels");
  IlluminationComponents out;
  const cv::Mat lighting = LinearImage(log_illumination);
  cv::Mat camera;
  image.convertTo(camera, CV_MAKETYPE(CV_32F, image.channels()),
                  image.depth() == CV_16U ? 255.0 / 65535.0 : 1.0);
  cv::Mat camera_value = LargestChannel(camera);
  cv::max(camera_value, options.grey_level, camera_value);
  out.luminance_step = options.grey_level / LargestChannel(LinearImage(log_invariant));
  if (lighting.channels() == 3) {
    std::vector<cv::Mat> hsv;
    cv::split(color::RgbToHsv(lighting), hsv);
    out.luminance = hsv[2];
    out.saturation = hsv[1];
    out.saturation_step = options.grey_level / camera_value;
  } else {
    out.luminance = lighting;
  }
  return out;
}

cv::Mat InformationMap(const cv::Mat& values, const cv::Mat& steps, const stats::GammaFit& fit) {
  if (values.type() != CV_32FC1 || steps.type() != CV_32FC1 || values.size() != steps.size())
    throw std::invalid_argument("InformationMap: values and widths must be CV_32FC1 of one size");
  if (!(fit.alpha > 0.0 && fit.beta > 0.0))
    throw std::invalid_argument("InformationMap: the gamma fit has no positive α and β");
  // log p(x) = a log b - log Γ(a) + (a - 1) log x - b x   (eq. 6.16)
  const double a = fit.alpha, b = fit.beta;
  const double log_norm = a * std::log(b) - stats::LogGamma(a);
  cv::Mat info(values.size(), CV_32F);
  for (int y = 0; y < values.rows; ++y) {
    const float* v = values.ptr<float>(y);
    const float* d = steps.ptr<float>(y);
    float* out = info.ptr<float>(y);
    for (int x = 0; x < values.cols; ++x) {
      const double step = d[x], value = std::max<double>(v[x], 0.5 * step);
      out[x] = float(-(log_norm + (a - 1.0) * std::log(value) - b * value + std::log(step)));
    }
  }
  return info;
}

IlluminationModel LearnIlluminationModel(const InvariantImage& invariant,
                                         const std::vector<cv::Mat>& images,
                                         const std::vector<cv::Mat>& coverage,
                                         const IlluminationModelOptions& options) {
  if (!(options.kappa >= 0.0 && options.kappa < 1.0) || !(options.grey_level > 0.0))
    throw std::invalid_argument(
        "LearnIlluminationModel: kappa must be in [0, 1) and grey_level > 0");
  if (images.size() != invariant.log_illumination.size() ||
      (!coverage.empty() && coverage.size() != images.size()))
    throw std::invalid_argument("LearnIlluminationModel: " + std::to_string(images.size()) +
                                " images for " + std::to_string(invariant.log_illumination.size()) +
                                " illumination images");
  std::vector<IlluminationComponents> components;
  std::vector<double> luminance, saturation;
  for (std::size_t m = 0; m < images.size(); ++m) {
    components.push_back(ComputeIlluminationComponents(
        invariant.log_illumination[m], invariant.log_invariant, images[m], options));
    const cv::Mat valid = Valid(invariant, coverage, m);
    AppendSamples(components.back().luminance, valid, luminance);
    if (!components.back().saturation.empty())
      AppendSamples(components.back().saturation, valid, saturation);
  }
  if (luminance.empty()) throw std::invalid_argument("LearnIlluminationModel: no pixel is covered");
  IlluminationModel model;
  model.luminance = stats::FitGammaML(luminance);
  if (!saturation.empty()) model.saturation = stats::FitGammaML(saturation);
  std::vector<cv::Mat> information;
  double sum = 0.0, count = 0.0;
  for (std::size_t m = 0; m < images.size(); ++m) {
    information.push_back(
        InformationMap(components[m].luminance, components[m].luminance_step, model.luminance));
    const cv::Mat valid = Valid(invariant, coverage, m);
    const int n = cv::countNonZero(valid);
    if (n > 0) sum += cv::mean(information.back(), valid)[0] * n;
    count += n;
  }
  model.mean_information = sum / count;
  model.threshold = model.mean_information / (1.0 - options.kappa);  // eq. 6.18
  for (std::size_t m = 0; m < images.size(); ++m)
    model.shapes.push_back((information[m] > model.threshold) & Valid(invariant, coverage, m));
  return model;
}

}  // namespace novelty::illumination
