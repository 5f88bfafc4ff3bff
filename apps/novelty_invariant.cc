// novelty-invariant: the illumination-invariant image of one viewpoint from images of it under
// different lights (thesis 6.1.2), its illumination images (eq. 6.14) and their statistics
// (6.2: gamma models, information maps, the shapes of highlights and strong shadows).
//
//   novelty-invariant DIR --out OUT [--colour per-channel|luminance-chromaticity]
//                     [--min-intensity 3] [--min-lightings 2] [--kappa 0.5]
//
// DIR holds the lightings (every image file in name order; see sensors/dataset/
// lighting_folder_reader.h) and optionally mask.png; in the MIT Intrinsic Images layout
// (reflectance.png, shading.png, diffuse.png) the decomposition is also scored with the
// benchmark's LMSE. OUT gets invariant.png (linear, the inputs' bit depth and scale),
// illumination/ (L = I / R as 8 bits, 1 → 128), information/ (i_Y in false colour, 0 … 2 T_Y),
// shapes/ (255 where i_Y > T_Y), panels/, model.csv, findings.csv and report.html.
#include <tclap/CmdLine.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "apps/command_line.h"
#include "apps/shell/output_folder.h"
#include "apps/shell/program.h"
#include "apps/shell/table_flags.h"
#include "core/false_color.h"
#include "core/float_image.h"
#include "core/range_check.h"
#include "core/same_file.h"
#include "core/write_rgb_image.h"
#include "eval/findings_table.h"
#include "eval/html_report.h"
#include "eval/lmse.h"
#include "eval/side_by_side.h"
#include "maps/illumination/illumination_model.h"
#include "maps/illumination/invariant_image.h"
#include "mrpt_plugins/illumination_invariant_map_options.h"
#include "sensors/dataset/lighting_folder_reader.h"

using namespace novelty;
namespace fs = std::filesystem;

namespace {

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

void WriteLinear(const std::string& path, const cv::Mat& linear, int depth) {
  cv::Mat out, bgr;
  linear.convertTo(out, CV_MAKETYPE(depth, linear.channels()),
                   depth == CV_16U ? 65535.0 / 255.0 : 1.0);
  if (out.channels() == 3)
    cv::cvtColor(out, bgr, cv::COLOR_RGB2BGR);
  else
    bgr = out;
  if (!cv::imwrite(path, bgr)) throw std::runtime_error(path + ": cannot be written");
}

std::string Stem(const std::string& name) {
  return fs::path(name).stem().string();
}

// Histogram of a component's samples against its fitted gamma density (fig. 6.4 c, d).
std::string HistogramPlot(const std::string& title, const std::vector<cv::Mat>& values,
                          const std::vector<cv::Mat>& valid, const stats::GammaFit& fit,
                          double max_value) {
  const int bins = 100;
  std::vector<double> counts(bins, 0.0);
  double total = 0.0;
  for (std::size_t m = 0; m < values.size(); ++m)
    for (int y = 0; y < values[m].rows; ++y)
      for (int x = 0; x < values[m].cols; ++x) {
        if (!valid[m].at<uchar>(y, x)) continue;
        const double v = values[m].at<float>(y, x);
        const int b = int(v / max_value * bins);
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

int Run(int argc, char** argv) {
  apps::CommandLine cmd(
      "Illumination-invariant image, illumination images and their statistics from images of "
      "one viewpoint under different lights (thesis 6.1.2, 6.2).",
      "0.1");
  TCLAP::UnlabeledValueArg<std::string> in("folder", "Folder of lightings", true, "", "DIR", cmd);
  TCLAP::ValueArg<std::string> out("o", "out", "Output folder", true, "", "OUT", cmd);
  // The invariant image's and model's options are CIlluminationInvariantMap's, with its
  // table's defaults.
  apps::TableFlags<mrpt_plugins::IlluminationInvariantMapConfig> options(
      cmd, {{"colour", "colour"},
            {"min_intensity", "min-intensity"},
            {"min_lightings", "min-lightings"},
            {"kappa", "kappa"}});
  cmd.Parse(argc, argv);
  const illumination::IlluminationMapOptions map = options.Values().map;
  const illumination::InvariantImageOptions& inv_options = map.invariant;
  const illumination::IlluminationModelOptions& model_options = map.model;
  apps::OutputFolder out_folder("novelty-invariant", out.getValue(), {in.getValue()});

  const auto start = std::chrono::steady_clock::now();
  const sensors::LightingFolder folder = sensors::ReadLightingFolder(in.getValue());
  const int m_count = int(folder.images.size());
  if (inv_options.min_lightings > m_count)
    throw std::invalid_argument("--min-lightings " + std::to_string(inv_options.min_lightings) +
                                " exceeds the " + std::to_string(m_count) + " lightings in " +
                                in.getValue());
  std::fprintf(stderr, "[novelty-invariant] %d lightings of %dx%d from %s\n", m_count,
               folder.images[0].cols, folder.images[0].rows, in.getValue().c_str());
  const std::vector<cv::Mat> coverage =
      folder.mask.empty() ? std::vector<cv::Mat>{} : std::vector<cv::Mat>(m_count, folder.mask);
  const illumination::InvariantImage invariant =
      illumination::ComputeInvariantImage(folder.images, coverage, inv_options);
  const illumination::IlluminationModel model =
      illumination::LearnIlluminationModel(invariant, coverage, model_options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const fs::path dir = out_folder.path();
  for (const char* sub : {"illumination", "information", "shapes", "panels"})
    fs::create_directories(dir / sub);
  const cv::Mat reflectance = illumination::LinearImage(invariant.log_invariant, invariant.covered);
  WriteLinear((dir / "invariant.png").string(), reflectance, folder.images[0].depth());
  double white = 0.0;
  for (const cv::Mat& im : folder.images)
    white = std::max(white, Percentile99(core::ToFloat255(im)));

  eval::HtmlReport report("novelty-invariant: " + in.getValue());
  report.Heading("Invariant image");
  core::WriteRgbImage((dir / "invariant_display.png").string(), Display(reflectance, white));
  report.Image("invariant_display.png",
               "illumination-invariant image R (linear, shown with gamma 1/2.2)");

  std::vector<cv::Mat> luminance, saturation, valid;
  std::vector<std::vector<std::string>> rows;
  for (int m = 0; m < m_count; ++m) {
    const illumination::IlluminationComponents c =
        illumination::ComputeIlluminationComponents(invariant.log_illumination[m]);
    const cv::Mat information =
        illumination::InformationMap(c.luminance, model.luminance_step, model.luminance);
    cv::Mat ok = invariant.covered.clone();
    luminance.push_back(c.luminance);
    saturation.push_back(c.saturation);
    valid.push_back(ok);
    const std::string stem = Stem(folder.names[m]);
    cv::Mat lighting = illumination::LinearImage(invariant.log_illumination[m], invariant.covered),
            lighting8;
    ToRgb(lighting).convertTo(lighting8, CV_8UC3, 128.0);
    core::WriteRgbImage((dir / "illumination" / (stem + ".png")).string(), lighting8);
    cv::Mat info_shown = information.clone();
    info_shown.setTo(std::nanf(""), invariant.covered == 0);
    const cv::Mat info_rgb = core::FalseColor(info_shown, 2.0 * model.threshold);
    core::WriteRgbImage((dir / "information" / (stem + ".png")).string(), info_rgb);
    const cv::Mat shape_rgb = ToRgb(model.shapes[m]);
    if (!cv::imwrite((dir / "shapes" / (stem + ".png")).string(), model.shapes[m]))
      throw std::runtime_error((dir / "shapes" / (stem + ".png")).string() + ": cannot be written");
    const std::string panel = "panels/" + stem + ".png";
    core::WriteRgbImage(
        (dir / panel).string(),
        eval::SideBySide(
            {Display(core::ToFloat255(folder.images[m]), white), lighting8, info_rgb, shape_rgb}, 4,
            {folder.names[m], "illumination (1 = 128)", "information i_Y", "i_Y > T_Y"}));
    report.Image(panel, folder.names[m]);
    const double share =
        100.0 * cv::countNonZero(model.shapes[m]) / std::max(1, cv::countNonZero(ok));
    rows.push_back({folder.names[m], cv::format("%.2f", share)});
  }

  std::ofstream model_csv(dir / "model.csv");
  model_csv << "a_Y,b_Y,a_S,b_S,mean_information_Y,T_Y,kappa,lightings\n"
            << model.luminance.alpha << "," << model.luminance.beta << "," << model.saturation.alpha
            << "," << model.saturation.beta << "," << model.mean_information << ","
            << model.threshold << "," << model_options.kappa << "," << m_count << "\n";
  eval::FindingsTable findings;
  std::printf(
      "%d lightings, %.2f s; gamma luminance a_Y %.3f b_Y %.3f, saturation a_S %.3f "
      "b_S %.3f; T_Y %.3f (mean information %.3f, kappa %.2f)\n",
      m_count, seconds, model.luminance.alpha, model.luminance.beta, model.saturation.alpha,
      model.saturation.beta, model.threshold, model.mean_information, model_options.kappa);
  report.Heading("Illumination statistics (6.2)");
  report.Table(
      {"a_Y", "b_Y", "a_S", "b_S", "mean i_Y", "T_Y", "κ"},
      {{cv::format("%.3f", model.luminance.alpha), cv::format("%.3f", model.luminance.beta),
        cv::format("%.3f", model.saturation.alpha), cv::format("%.3f", model.saturation.beta),
        cv::format("%.3f", model.mean_information), cv::format("%.3f", model.threshold),
        cv::format("%.2f", model_options.kappa)}});
  report.Raw(HistogramPlot("luminance of the illumination images", luminance, valid,
                           model.luminance, 3.0));
  if (model.saturation.alpha > 0)
    report.Raw(HistogramPlot("saturation of the illumination images", saturation, valid,
                             model.saturation, 1.0));
  report.Table({"lighting", "% of pixels above T_Y"}, rows);

  if (!folder.reflectance.empty() && !folder.shading.empty() && !folder.diffuse.empty() &&
      !folder.mask.empty()) {
    // The benchmark's protocol: shading = diffuse image / reflectance estimate, in grey.
    cv::Mat shading, grey_shading, true_shading = folder.shading;
    cv::divide(ToRgb(folder.diffuse), ToRgb(reflectance), shading);
    shading.setTo(cv::Scalar::all(0), folder.mask == 0);
    grey_shading = core::ChannelMean(shading);
    true_shading = core::ChannelMean(true_shading);
    const eval::IntrinsicScore s = eval::ScoreIntrinsic(true_shading, folder.reflectance,
                                                        grey_shading, reflectance, folder.mask);
    findings.Add("LMSE", eval::NumberText(s.lmse),
                 "(reported; MIT grey reference 0.0127 mean of 4)");
    findings.Add("LMSE shading", eval::NumberText(s.shading));
    findings.Add("LMSE reflectance", eval::NumberText(s.reflectance));
    std::printf("LMSE %.5f (shading %.5f, reflectance %.5f)\n", s.lmse, s.shading, s.reflectance);
    report.Heading("Against the ground truth (MIT Intrinsic Images LMSE)");
    report.Table({"LMSE", "shading", "reflectance"},
                 {{cv::format("%.5f", s.lmse), cv::format("%.5f", s.shading),
                   cv::format("%.5f", s.reflectance)}});
  }
  findings.Add("lightings", std::to_string(m_count));
  findings.Add("T_Y", eval::NumberText(model.threshold));
  findings.Add("seconds", eval::NumberText(seconds));
  findings.WriteCsv((dir / "findings.csv").string());
  report.Save((dir / "report.html").string());
  out_folder.Commit();
  std::printf("→ %s/report.html\n", out_folder.final_path().c_str());
  return apps::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-invariant", [&] { return Run(argc, argv); });
}
