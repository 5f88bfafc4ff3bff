#include "experiments/invariant_image_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

#include "core/false_color.h"
#include "core/float_image.h"
#include "core/write_rgb_image.h"
#include "eval/html_report.h"
#include "eval/side_by_side.h"
#include "maps/illumination/illumination_model.h"
#include "maps/illumination/invariant_image.h"
#include "sensors/dataset/lighting_folder_reader.h"

namespace novelty::experiments {
namespace {

namespace fs = std::filesystem;

cv::Mat ToRgb(const cv::Mat& image) {
  if (image.channels() == 3) return image;
  cv::Mat rgb;
  cv::cvtColor(image, rgb, cv::COLOR_GRAY2RGB);
  return rgb;
}

// The 99th percentile of a float image's values (white for the display of linear images).
double Percentile99(const cv::Mat& f) {
  const cv::Mat flat = f.clone().reshape(1, 1);
  std::vector<float> v(flat.begin<float>(), flat.end<float>());
  if (v.empty()) return 1.0;
  std::nth_element(v.begin(), v.begin() + v.size() * 99 / 100, v.end());
  return std::max(1e-6f, v[v.size() * 99 / 100]);
}

// A linear float image for the eye: `white` → 255, then gamma 1/2.2.
cv::Mat Display(const cv::Mat& linear, double white) {
  cv::Mat f = linear / white, out;
  cv::max(f, 0.0, f);
  cv::min(f, 1.0, f);
  cv::pow(f, 1.0 / 2.2, f);
  ToRgb(f).convertTo(out, CV_8UC3, 255.0);
  return out;
}

void WriteImage(const fs::path& path, const cv::Mat& image) {
  if (!cv::imwrite(path.string(), image))
    throw std::runtime_error(path.string() + ": cannot be written");
}

// Linear values in the inputs' bit depth and scale (0…255 as 8 bits, ×257 as 16 bits).
void WriteLinear(const fs::path& path, const cv::Mat& linear, int depth) {
  cv::Mat out, bgr;
  linear.convertTo(out, CV_MAKETYPE(depth, linear.channels()),
                   depth == CV_16U ? 65535.0 / 255.0 : 1.0);
  if (out.channels() == 3)
    cv::cvtColor(out, bgr, cv::COLOR_RGB2BGR);
  else
    bgr = out;
  WriteImage(path, bgr);
}

// Histogram of a component's samples against its fitted gamma density (fig. 6.4 c, d).
std::string HistogramPlot(const std::string& title, const std::vector<cv::Mat>& values,
                          const cv::Mat& valid, const stats::GammaFit& fit, double max_value) {
  const int bins = 100;
  std::vector<double> counts(bins, 0.0);
  double total = 0.0;
  for (const cv::Mat& v : values)
    for (int y = 0; y < v.rows; ++y)
      for (int x = 0; x < v.cols; ++x) {
        if (!valid.at<uchar>(y, x)) continue;
        const int b = int(v.at<float>(y, x) / max_value * bins);
        if (b >= 0 && b < bins) counts[b] += 1.0;
        total += 1.0;
      }
  eval::PlotSeries hist{"histogram (density)", "#1f77b4", {}, 0.0};
  eval::PlotSeries gamma{"gamma fit (eq. 6.16)", "#d62728", {}, 0.0};
  const double width = max_value / bins;
  const double lognorm = fit.alpha * std::log(fit.beta) - std::lgamma(fit.alpha);
  for (int b = 0; b < bins; ++b) {
    const double x = (b + 0.5) * width;
    hist.points.push_back({x, total > 0 ? counts[b] / (total * width) : 0.0});
    gamma.points.push_back({x, std::exp(lognorm + (fit.alpha - 1.0) * std::log(x) - fit.beta * x)});
  }
  return eval::SvgLinePlot(title, "value", "density", {hist, gamma});
}

struct LearntFolder {
  sensors::LightingFolder folder;
  illumination::InvariantImage invariant;
  illumination::IlluminationModel model;
  cv::Mat reflectance;  // linear R
  double white = 0.0;   // the inputs' 99th percentile, white of the displays
};

// Per lighting: its illumination image, information map, shapes and panel; the components for
// the histograms; a table row of the share above T_Y.
void WriteLightings(const LearntFolder& l, const fs::path& dir, eval::HtmlReport& report,
                    std::vector<cv::Mat>& luminance, std::vector<cv::Mat>& saturation,
                    std::vector<std::vector<std::string>>& rows) {
  for (const char* sub : {"illumination", "information", "shapes", "panels"})
    fs::create_directories(dir / sub);
  const cv::Mat& covered = l.invariant.covered;
  for (std::size_t m = 0; m < l.folder.images.size(); ++m) {
    const illumination::IlluminationComponents c =
        illumination::ComputeIlluminationComponents(l.invariant.log_illumination[m]);
    luminance.push_back(c.luminance);
    saturation.push_back(c.saturation);
    const std::string& name = l.folder.names[m];
    const std::string stem = fs::path(name).stem().string() + ".png";
    cv::Mat lighting8;
    ToRgb(illumination::LinearImage(l.invariant.log_illumination[m], covered))
        .convertTo(lighting8, CV_8UC3, 128.0);
    core::WriteRgbImage((dir / "illumination" / stem).string(), lighting8);
    cv::Mat information =
        illumination::InformationMap(c.luminance, l.model.luminance_step, l.model.luminance);
    information.setTo(std::nanf(""), covered == 0);
    const cv::Mat info_rgb = core::FalseColor(information, 2.0 * l.model.threshold);
    core::WriteRgbImage((dir / "information" / stem).string(), info_rgb);
    WriteImage(dir / "shapes" / stem, l.model.shapes[m]);
    core::WriteRgbImage(
        (dir / "panels" / stem).string(),
        eval::SideBySide({Display(core::ToFloat255(l.folder.images[m]), l.white), lighting8,
                          info_rgb, ToRgb(l.model.shapes[m])},
                         4, {name, "illumination (1 = 128)", "information i_Y", "i_Y > T_Y"}));
    report.Image("panels/" + stem, name);
    const double share =
        100.0 * cv::countNonZero(l.model.shapes[m]) / std::max(1, cv::countNonZero(covered));
    rows.push_back({name, cv::format("%.2f", share)});
  }
}

void WriteModel(const LearntFolder& l, double kappa, const fs::path& dir,
                eval::HtmlReport& report) {
  const illumination::IlluminationModel& model = l.model;
  std::ofstream csv(dir / "model.csv");
  csv << "a_Y,b_Y,a_S,b_S,mean_information_Y,T_Y,kappa,lightings\n"
      << model.luminance.alpha << "," << model.luminance.beta << "," << model.saturation.alpha
      << "," << model.saturation.beta << "," << model.mean_information << "," << model.threshold
      << "," << kappa << "," << l.folder.images.size() << "\n";
  report.Heading("Illumination statistics (6.2)");
  report.Table(
      {"a_Y", "b_Y", "a_S", "b_S", "mean i_Y (nats)", "T_Y (nats)", "κ"},
      {{cv::format("%.3f", model.luminance.alpha), cv::format("%.3f", model.luminance.beta),
        cv::format("%.3f", model.saturation.alpha), cv::format("%.3f", model.saturation.beta),
        cv::format("%.3f", model.mean_information), cv::format("%.3f", model.threshold),
        cv::format("%.2f", kappa)}});
}

// The benchmark's protocol: shading = diffuse image / reflectance estimate, in grey.
std::optional<eval::IntrinsicScore> ScoreMit(const LearntFolder& l) {
  const sensors::LightingFolder& f = l.folder;
  if (f.reflectance.empty() || f.shading.empty() || f.diffuse.empty() || f.mask.empty())
    return std::nullopt;
  cv::Mat shading;
  cv::divide(ToRgb(f.diffuse), ToRgb(l.reflectance), shading);
  shading.setTo(cv::Scalar::all(0), f.mask == 0);
  return eval::ScoreIntrinsic(core::ChannelMean(f.shading), f.reflectance,
                              core::ChannelMean(shading), l.reflectance, f.mask);
}

}  // namespace

InvariantImageRunResult RunInvariantImage(const std::string& folder_path,
                                          const illumination::IlluminationMapOptions& map,
                                          const std::string& out_dir,
                                          const std::function<void(const std::string&)>& status,
                                          const sensors::LightingFolderOptions& pick) {
  const auto start = std::chrono::steady_clock::now();
  LearntFolder l;
  l.folder = sensors::ReadLightingFolder(folder_path, pick);
  const int m_count = int(l.folder.images.size());
  if (map.invariant.min_lightings > m_count)
    throw std::invalid_argument("min_lightings " + std::to_string(map.invariant.min_lightings) +
                                " exceeds the " + std::to_string(m_count) + " lightings in " +
                                folder_path);
  if (status)
    status(cv::format("%d lightings of %dx%d from %s", m_count, l.folder.images[0].cols,
                      l.folder.images[0].rows, folder_path.c_str()) +
           (l.folder.left_out.empty()
                ? std::string()
                : cv::format(" (%d images left out by the patterns, first %s)",
                             int(l.folder.left_out.size()), l.folder.left_out[0].c_str())));
  const std::vector<cv::Mat> coverage =
      l.folder.mask.empty() ? std::vector<cv::Mat>{} : std::vector<cv::Mat>(m_count, l.folder.mask);
  l.invariant = illumination::ComputeInvariantImage(l.folder.images, coverage, map.invariant);
  l.model = illumination::LearnIlluminationModel(l.invariant, coverage, map.model);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  l.reflectance = illumination::LinearImage(l.invariant.log_invariant, l.invariant.covered);
  for (const cv::Mat& im : l.folder.images)
    l.white = std::max(l.white, Percentile99(core::ToFloat255(im)));

  const fs::path dir(out_dir);
  WriteLinear(dir / "invariant.png", l.reflectance, l.folder.images[0].depth());
  eval::HtmlReport report("novelty-invariant: " + folder_path);
  report.Heading("Invariant image");
  core::WriteRgbImage((dir / "invariant_display.png").string(), Display(l.reflectance, l.white));
  report.Image("invariant_display.png",
               "illumination-invariant image R (linear, shown with gamma 1/2.2)");
  std::vector<cv::Mat> luminance, saturation;
  std::vector<std::vector<std::string>> rows;
  WriteLightings(l, dir, report, luminance, saturation, rows);
  WriteModel(l, map.model.kappa, dir, report);
  report.Raw(HistogramPlot("luminance of the illumination images", luminance, l.invariant.covered,
                           l.model.luminance, 3.0));
  if (l.model.saturation.alpha > 0)
    report.Raw(HistogramPlot("saturation of the illumination images", saturation,
                             l.invariant.covered, l.model.saturation, 1.0));
  report.Table({"lighting", "pixels above T_Y (%)"}, rows);

  InvariantImageRunResult r;
  r.lightings = m_count;
  r.threshold = l.model.threshold;
  r.lmse = ScoreMit(l);
  r.summary = cv::format(
      "%d lightings, %.2f s; gamma luminance a_Y %.3f b_Y %.3f, saturation a_S %.3f b_S %.3f; "
      "T_Y %.3f (mean information %.3f, kappa %.2f)",
      m_count, seconds, l.model.luminance.alpha, l.model.luminance.beta, l.model.saturation.alpha,
      l.model.saturation.beta, l.model.threshold, l.model.mean_information, map.model.kappa);
  if (r.lmse) {
    const eval::IntrinsicScore& s = *r.lmse;
    r.findings.Add("LMSE", eval::NumberText(s.lmse),
                   "(reported; MIT grey reference 0.0127 mean of 4)");
    r.findings.Add("LMSE shading", eval::NumberText(s.shading));
    r.findings.Add("LMSE reflectance", eval::NumberText(s.reflectance));
    r.summary += cv::format("; LMSE %.5f (shading %.5f, reflectance %.5f)", s.lmse, s.shading,
                            s.reflectance);
    report.Heading("Against the ground truth (MIT Intrinsic Images LMSE)");
    report.Table({"LMSE", "shading", "reflectance"},
                 {{cv::format("%.5f", s.lmse), cv::format("%.5f", s.shading),
                   cv::format("%.5f", s.reflectance)}});
  }
  r.findings.Add("lightings", std::to_string(m_count));
  r.findings.Add("T_Y", eval::NumberText(l.model.threshold));
  r.findings.Add("seconds", eval::NumberText(seconds));
  r.findings.WriteCsv((dir / "findings.csv").string());
  report.Save((dir / "report.html").string());
  return r;
}

}  // namespace novelty::experiments
