#include "experiments/illumination_experiment.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>

#include "core/false_color.h"
#include "core/float_image.h"
#include "core/write_rgb_image.h"
#include "eval/html_report.h"
#include "eval/roc.h"
#include "eval/roc_plot.h"
#include "eval/side_by_side.h"
#include "maps/illumination/gradient_correlation.h"
#include "maps/illumination/illumination_model.h"
#include "maps/illumination/illumination_novelty.h"
#include "maps/illumination/invariant_image.h"
#include "maps/illumination/lighting_threshold.h"
#include "maps/illumination/spherical_color_change.h"
#include "maps/views/view_synthesis.h"
#include "sensors/rawlog/camera_pose_observation.h"
#include "sensors/rawlog/rawlog_frame_reader.h"
#include "sensors/rawlog/rig_frame_reader.h"
#include "sim/output/ground_truth_format.h"
#include "sim/output/ground_truth_reader.h"

namespace novelty::experiments {
namespace {

namespace fs = std::filesystem;

void Status(const IlluminationExperimentOptions& o, const std::string& line) {
  if (o.status) o.status(line);
}

void Progress(const IlluminationExperimentOptions& o, const std::string& stage, int done,
              int total) {
  if (o.progress) o.progress(stage, done, total);
}

const sim::GroundTruthReader::Phase& FindPhase(const sim::GroundTruthReader& truth,
                                               const std::string& name) {
  for (const auto& p : truth.Phases())
    if (p.name == name) return p;
  std::string known;
  for (const auto& p : truth.Phases()) known += (known.empty() ? "" : ", ") + p.name;
  throw std::invalid_argument("no phase '" + name + "' in " + truth.dir() +
                              "/events.csv (phases: " + (known.empty() ? "none" : known) + ")");
}

// One test frame as the evaluation sees it.
struct TestFrame {
  int index = 0;
  cv::Mat image, novelty, truth;
  cv::Mat evaluated;  // CV_8UC1: the pixels scored (covered by the invariant and every reference)
  cv::Mat invariant;  // CV_8UC3, for the panel
  std::vector<cv::Mat> references;  // [0] the baselines' reference; the others for comparison
};

struct Method {
  std::string name, colour;
  std::vector<double> scores;  // per evaluated pixel of all test frames
};

// Everything scored over the test frames.
struct Evaluation {
  // Names as findings.csv spells them: novelty Δ (eq. 6.24), NGC's 1 - ρ, SCT's distance.
  std::vector<Method> methods = {
      {"novelty", "#d62728", {}}, {"NGC", "#1f77b4", {}}, {"SCT", "#2ca02c", {}}};
  std::vector<bool> positive, lighting_only;
  /// alternatives[k][r]: baseline k (0 NGC, 1 SCT) against reference r, same pixels.
  std::vector<std::vector<std::vector<double>>> alternatives{2};
  long candidate_pixels = 0;  // pixels of the test frames, scored or not
  int tested = 0;
  double detect_seconds = 0.0;
};

cv::Mat BaselineNovelty(int k, const cv::Mat& image, const cv::Mat& reference) {
  return k == 0 ? illumination::GradientCorrelationChange(image, reference)
                : illumination::SphericalColorChange(image, reference);
}

// Scores one test frame and writes its panel.
void Score(const TestFrame& t, Evaluation& e, eval::HtmlReport& report, const fs::path& dir) {
  const cv::Mat& reference = t.references.front();
  const cv::Mat maps[3] = {t.novelty, BaselineNovelty(0, t.image, reference),
                           BaselineNovelty(1, t.image, reference)};
  cv::Mat relative;
  const cv::Mat grey_obs = core::ChannelMean(t.image),
                grey_ref = core::ChannelMean(reference) + 1.0f;
  cv::divide(cv::abs(grey_obs - grey_ref + 1.0f), grey_ref, relative);
  e.alternatives[0].resize(t.references.size());
  e.alternatives[1].resize(t.references.size());
  std::vector<cv::Mat> others[2];
  for (int k = 0; k < 2; ++k)
    for (std::size_t r = 1; r < t.references.size(); ++r)
      others[k].push_back(BaselineNovelty(k, t.image, t.references[r]));
  e.candidate_pixels += long(t.image.total());
  for (int y = 0; y < t.image.rows; ++y)
    for (int x = 0; x < t.image.cols; ++x) {
      if (!t.evaluated.at<uchar>(y, x)) continue;
      // Added and removed objects are both novelty (the thesis's table scene: a roll gone).
      const bool changed = t.truth.at<uchar>(y, x) != 0;
      e.positive.push_back(changed);
      e.lighting_only.push_back(!changed && relative.at<float>(y, x) > 0.25f);
      for (int k = 0; k < 3; ++k) e.methods[k].scores.push_back(maps[k].at<float>(y, x));
      for (int k = 0; k < 2; ++k) {
        e.alternatives[k][0].push_back(maps[k + 1].at<float>(y, x));
        for (std::size_t r = 1; r < t.references.size(); ++r)
          e.alternatives[k][r].push_back(others[k][r - 1].at<float>(y, x));
      }
    }
  // Δ spans decades: shown up to its 99th percentile in the frame.
  cv::Mat sorted = t.novelty.clone().reshape(1, 1);
  cv::sort(sorted, sorted, cv::SORT_ASCENDING);
  const double max_novelty = sorted.at<float>(0, int(sorted.cols * 0.99));
  cv::Mat truth_rgb;
  cv::cvtColor(t.truth, truth_rgb, cv::COLOR_GRAY2RGB);
  truth_rgb.setTo(cv::Scalar(90, 90, 90), ~t.evaluated & (t.truth == 0));  // the thesis's grey
  const std::string panel = cv::format("panels/%06d.png", t.index);
  core::WriteRgbImage(
      (dir / panel).string(),
      eval::SideBySide(
          {t.image, reference, t.invariant, core::FalseColor(maps[0], std::max(1e-6, max_novelty)),
           core::FalseColor(maps[1], 1.0), core::FalseColor(maps[2], 0.5), truth_rgb},
          4,
          {cv::format("frame %d", t.index), "reference", "invariant image", "novelty (6.3)",
           "NGC 1 - rho", "SCT distance", "ground truth (grey: not scored)"}));
  report.Image(panel, cv::format("test frame %d", t.index));
  ++e.tested;
}

struct LearntSummary {
  std::string summary;  // for the report: what was learnt
  std::vector<std::pair<std::string, std::string>> findings;
  double decision_threshold = NAN;  // τ from the training lightings (NaN: none)
};

// Δ at the τ the training lightings chose, as a user without ground truth would decide: the
// share of unchanged pixels above it (against the rate it was learnt for) and of novel ones.
void AddDecisionFindings(const Evaluation& e, double tau, double target,
                         eval::FindingsTable& findings) {
  if (std::isnan(tau)) {
    findings.Add("decision threshold",
                 "none (needs min_lightings + 1 lightings, threshold_viewpoints > 0 and a "
                 "held-out lighting with an invariant image)");
    return;
  }
  const eval::RocPoint at = eval::OperatingPoint(e.methods[0].scores, e.positive, tau);
  findings.Add("decision threshold τ from the training lightings (nats)", eval::NumberText(tau),
               "learnt at " + eval::PercentText(target) + " false alarms");
  findings.Add("novelty at τ: FPR", eval::PercentText(at.fpr),
               "(reported; learnt for " + eval::PercentText(target) + ")");
  findings.Add("novelty at τ: TPR", eval::PercentText(at.tpr), "(reported)");
}

// Writes roc.csv, findings.csv and report.html; returns what they say.
IlluminationExperimentResult Finish(const Evaluation& e, const LearntSummary& learnt,
                                    double false_alarm_rate, const std::string& lightings_name,
                                    double learn_seconds, const fs::path& dir,
                                    eval::HtmlReport& report) {
  std::vector<eval::Roc> rocs;
  for (const Method& m : e.methods) rocs.push_back(eval::ComputeRoc(m.scores, e.positive));
  IlluminationExperimentResult result;
  eval::FindingsTable& findings = result.findings;
  std::vector<std::vector<std::string>>& rows = result.methods;
  std::vector<eval::PlotSeries> curves;
  for (size_t k = 0; k < e.methods.size(); ++k) {
    const eval::Roc& roc = rocs[k];
    // Lighting-only change flagged at the threshold that finds 90 % of the object.
    double threshold = -INFINITY;
    for (const auto& p : roc.points)
      if (p.tpr >= 0.9) {
        threshold = p.threshold;
        break;
      }
    long flagged = 0, lighting = 0;
    for (size_t j = 0; j < e.positive.size(); ++j)
      if (e.lighting_only[j]) ++lighting, flagged += e.methods[k].scores[j] >= threshold;
    const double lighting_share = lighting ? double(flagged) / lighting : 0.0;
    const std::string& name = e.methods[k].name;
    rows.push_back({name, eval::PercentText(roc.TprAtFpr(0.01)),
                    eval::PercentText(roc.TprAtFpr(0.05)), eval::PercentText(roc.TprAtFpr(0.10)),
                    cv::format("%.3f", roc.auc), eval::PercentText(lighting_share)});
    findings.Add(name + ": TPR at FPR <= 1 %", eval::PercentText(roc.TprAtFpr(0.01)), "(reported)");
    findings.Add(name + ": TPR at FPR <= 5 %", eval::PercentText(roc.TprAtFpr(0.05)), "(reported)");
    if (k == 0)
      findings.Add(name + ": AUC", eval::NumberText(roc.auc), ">= 0.95", roc.auc >= 0.95);
    else
      findings.Add(name + ": AUC", eval::NumberText(roc.auc), "(reported)");
    findings.Add(name + ": lighting-only change flagged at TPR 90 %",
                 eval::PercentText(lighting_share), "(reported)");
    eval::PlotSeries s{name, e.methods[k].colour, {}, 0.0};
    for (const auto& p : roc.points) s.points.push_back({p.fpr, p.tpr});
    curves.push_back(s);
  }
  // Ahead of both baselines at every FPR ≤ 10 % (0.1 % steps).
  const std::optional<double> first_behind =
      eval::FirstFprNotAbove(rocs[0], {&rocs[1], &rocs[2]}, 0.10);
  const bool ahead = !first_behind;
  const double scored_share = double(e.positive.size()) / double(std::max(1L, e.candidate_pixels));
  findings.Add("novelty TPR above NGC and SCT at every FPR <= 10 % (0.1 % steps)",
               ahead ? "yes" : cv::format("no (from FPR %.1f %%)", 100 * *first_behind), "yes",
               ahead);
  findings.Add("test frames", std::to_string(e.tested));
  findings.Add("evaluated pixels", std::to_string(e.positive.size()));
  findings.Add("evaluated share of the test frames' pixels", eval::PercentText(scored_share));
  findings.Add("object pixels", std::to_string(rocs[0].positives));
  AddDecisionFindings(e, learnt.decision_threshold, false_alarm_rate, findings);
  for (const auto& [name, value] : learnt.findings) findings.Add(name, value);
  findings.Add("learning seconds", eval::NumberText(learn_seconds));
  findings.Add("detection ms per frame", eval::NumberText(1000.0 * e.detect_seconds / e.tested));
  // The baselines against every lighting as the reference: how much their result depends on the
  // one reference the thesis picks, and whether the novelty leads their best.
  const std::vector<double> lead_fprs = {0.01, 0.05};
  for (int k = 0; k < 2; ++k) {
    double auc_min = 1.0, auc_max = 0.0;
    std::vector<double> best_tpr(lead_fprs.size(), 0.0);
    for (const auto& scores : e.alternatives[k]) {
      const eval::Roc roc = eval::ComputeRoc(scores, e.positive);
      auc_min = std::min(auc_min, roc.auc);
      auc_max = std::max(auc_max, roc.auc);
      for (size_t f = 0; f < lead_fprs.size(); ++f)
        best_tpr[f] = std::max(best_tpr[f], roc.TprAtFpr(lead_fprs[f]));
    }
    const std::string& name = e.methods[k + 1].name;
    findings.Add(name + " over the " + std::to_string(e.alternatives[k].size()) + " " +
                     lightings_name + " as reference: AUC",
                 cv::format("%.3f to %.3f", auc_min, auc_max), "(reported)");
    for (size_t f = 0; f < lead_fprs.size(); ++f) {
      const double mine = rocs[0].TprAtFpr(lead_fprs[f]);
      findings.Add("novelty TPR above " + name +
                       "'s best reference at FPR <= " + eval::NumberText(100 * lead_fprs[f]) + " %",
                   eval::PercentText(mine) + " vs " + eval::PercentText(best_tpr[f]), "(reported)",
                   mine > best_tpr[f] || (mine == 1.0 && best_tpr[f] == 1.0));
    }
  }
  {
    std::ofstream roc_csv(dir / "roc.csv");
    roc_csv << "fpr,tpr_novelty,tpr_ngc,tpr_sct\n";
    for (int step = 0; step <= 1000; ++step) {
      const double fpr = step / 1000.0;
      roc_csv << fpr << "," << rocs[0].TprAtFpr(fpr) << "," << rocs[1].TprAtFpr(fpr) << ","
              << rocs[2].TprAtFpr(fpr) << "\n";
    }
  }
  report.Heading("ROC over the test frames' pixels");
  report.Raw(eval::SvgLinePlot("ROC", "FPR", "TPR", curves));
  report.Table({"method", "TPR at FPR 1 %", "TPR at FPR 5 %", "TPR at FPR 10 %", "AUC",
                "lighting-only change flagged at TPR 90 %"},
               rows);
  report.Paragraph(cv::format(
      "%d test frames, %zu evaluated pixels (%s of the frames' pixels; %d on the object); %s; "
      "novelty ahead of both baselines at every FPR <= 10 %%: %s.",
      e.tested, e.positive.size(), eval::PercentText(scored_share).c_str(), rocs[0].positives,
      learnt.summary.c_str(), ahead ? "yes" : "no"));
  findings.WriteCsv((dir / "findings.csv").string());
  report.Save((dir / "report.html").string());
  result.ahead = ahead;
  result.scored_share = scored_share;
  result.test_frames = e.tested;
  result.ms_per_test_frame = 1000.0 * e.detect_seconds / e.tested;
  return result;
}

cv::Mat NoveltyTruth(const sim::GroundTruthReader& truth, int frame, cv::Size size) {
  cv::Mat t = truth.Novelty(frame);
  if (t.empty() || t.size() != size)
    throw std::invalid_argument(truth.dir() + ": frame " + std::to_string(frame) +
                                " has no novelty mask of the images' size");
  return t;
}

// Frames of a rawlog by index: RGB-D frames, or the reference camera of stereo and trinocular
// rigs (no depth: the caller takes the ground truth's). Only frames `wanted` returns true for.
// Camera poses where the rawlog has them (novelty-poses' observations, with the frame's time).
template <typename Wanted>
std::map<int, core::Frame> ReadFrames(const std::string& rawlog, Wanted wanted) {
  std::map<int, core::Frame> frames;
  sensors::RawlogFrameReader reader(rawlog);
  for (core::Frame f; reader.Next(f);)
    if (wanted(f.index)) frames[f.index] = f;
  if (!frames.empty()) return frames;
  sensors::RigFrameReader rigs(rawlog);
  std::vector<mrpt::serialization::CSerializable::Ptr> others;
  for (sensors::RigFrame r; rigs.Next(r, &others); others.clear()) {
    if (!wanted(r.index)) continue;
    core::Frame& f = frames[r.index];
    f.index = r.index;
    f.time = r.time;
    f.rgb = r.images.front();
    f.camera = r.cameras.front();
    for (const auto& o : others)
      if (const auto p = std::dynamic_pointer_cast<mrpt::obs::CObservationRobotPose>(o);
          p && std::abs(mrpt::Clock::toDouble(p->timestamp) - r.time) < 1e-6) {
        f.T_world_cam = sensors::RobotPoseOf(*p) * r.robot_from_reference;
        f.pose_source = p->sensorLabel;
      }
  }
  return frames;
}

// One viewpoint, each training frame a lighting (6.4.1 washing machine, 6.4.2 plate).
double RunStatic(const std::string& rawlog, const sim::GroundTruthReader& truth,
                 const sim::GroundTruthReader::Phase& train,
                 const sim::GroundTruthReader::Phase& test, std::optional<int> reference_frame,
                 const IlluminationExperimentOptions& o, const fs::path& dir,
                 eval::HtmlReport& report, Evaluation& e, LearntSummary& learnt) {
  std::map<int, core::Frame> frames = ReadFrames(rawlog, [&](int i) {
    return (i >= train.first && i <= train.last) || (i >= test.first && i <= test.last) ||
           (reference_frame && i == *reference_frame);
  });
  std::vector<cv::Mat> training;
  for (int i = train.first; i <= train.last; ++i)
    if (frames.count(i)) training.push_back(frames[i].rgb);
  if (training.size() < 2)
    throw std::invalid_argument(rawlog + ": " + std::to_string(training.size()) +
                                " training frame(s) in phase '" + train.name +
                                "'; a single lighting gives no invariant image");
  const int ref_index = reference_frame.value_or(train.first);
  if (!frames.count(ref_index))
    throw std::invalid_argument("--reference-frame " + std::to_string(ref_index) +
                                " is not a frame of " + rawlog);
  const auto start = std::chrono::steady_clock::now();
  const illumination::InvariantImage invariant =
      illumination::ComputeInvariantImage(training, {}, o.map.invariant);
  const illumination::ZernikeMoments zernike(o.map.zernike);
  const illumination::ViewpointIllumination viewpoint = illumination::MakeViewpoint(
      invariant, illumination::LearnIlluminationModel(invariant, {}, o.map.model),
      o.map.novelty.min_region_pixels, &zernike);
  // τ as the map learns it (illumination_map.h), for the one viewpoint.
  const illumination::LightingThresholdOptions& to = o.map.threshold;
  if (to.viewpoints > 0 && int(training.size()) - 1 >= std::max(2, o.map.invariant.min_lightings)) {
    try {
      learnt.decision_threshold = illumination::ThresholdAtFalseAlarmRate(
          illumination::HeldOutLightingNovelty(training, {}, o.map.invariant, o.map.model,
                                               o.map.novelty, zernike)
              .values,
          to.false_alarm_rate);
    } catch (const std::invalid_argument& error) {  // too little left once one is out: no τ
      Status(o, std::string("no decision threshold: ") + error.what());
    }
  }
  const double learn_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Status(o, cv::format("learnt from %zu frames: T_Y %.2f, %zu stored shapes", training.size(),
                       viewpoint.model.threshold, viewpoint.shapes.size()));
  // The thesis's reference first, then every training frame.
  std::vector<cv::Mat> references = {frames[ref_index].rgb};
  for (int i = train.first; i <= train.last; ++i)
    if (frames.count(i) && i != ref_index) references.push_back(frames[i].rgb);
  const cv::Mat invariant8 = illumination::LinearImage8(invariant.log_invariant, invariant.covered);
  for (int i = test.first; i <= test.last; ++i) {
    if (!frames.count(i)) continue;
    TestFrame t;
    t.index = i;
    t.image = frames[i].rgb;
    t.truth = NoveltyTruth(truth, i, t.image.size());
    const auto t0 = std::chrono::steady_clock::now();
    const illumination::IlluminationNovelty n =
        illumination::DetectIlluminationNovelty(t.image, viewpoint, zernike, o.map.novelty);
    e.detect_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    t.novelty = n.novelty;
    t.evaluated = invariant.covered;
    t.invariant = invariant8;
    t.references = references;
    Score(t, e, report, dir);
    Progress(o, "test frames", e.tested, test.last - test.first + 1);
  }
  learnt.summary = cv::format("learnt from %zu frames, T_Y %.2f, %zu stored shapes",
                              training.size(), viewpoint.model.threshold, viewpoint.shapes.size());
  learnt.findings = {{"stored shapes", std::to_string(viewpoint.shapes.size())}};
  return learn_seconds;
}

// A moving camera, each phase one lighting's sequence (6.4.1 table scene, 6.4.2 specular scene).
double RunMoving(const std::string& rawlog, const sim::GroundTruthReader& truth,
                 const std::vector<const sim::GroundTruthReader::Phase*>& train,
                 const sim::GroundTruthReader::Phase& test, const IlluminationExperimentOptions& o,
                 const fs::path& dir, eval::HtmlReport& report, Evaluation& e,
                 LearntSummary& learnt) {
  auto phase_of = [&](int i) -> int {
    for (std::size_t m = 0; m < train.size(); ++m)
      if (i >= train[m]->first && i <= train[m]->last) return int(m);
    return i >= test.first && i <= test.last ? int(train.size()) : -1;
  };
  std::map<int, core::Frame> frames = ReadFrames(rawlog, [&](int i) { return phase_of(i) >= 0; });
  int depth_from_truth = 0, without_pose = 0;
  for (auto it = frames.begin(); it != frames.end();) {
    const int i = it->first;
    core::Frame& f = it->second;
    if (o.poses_from_rawlog) {
      if (!f.T_world_cam) {  // the tracker lost the LEDs: the frame is skipped and counted
        ++without_pose;
        it = frames.erase(it);
        continue;
      }
    } else {
      const auto pose = truth.CameraPoses().find(i);
      if (pose == truth.CameraPoses().end())
        throw std::invalid_argument(truth.dir() + ": no camera pose for frame " +
                                    std::to_string(i));
      f.T_world_cam = pose->second;
      f.pose_source = "groundtruth";
    }
    if (f.depth.empty() && phase_of(i) < int(train.size())) {  // test frames need no depth
      f.depth = truth.Depth(i);
      ++depth_from_truth;
      if (f.depth.size() != f.rgb.size())
        throw std::invalid_argument(truth.dir() + ": frame " + std::to_string(i) +
                                    " has no depth map of the image's size");
    }
    ++it;
  }
  if (without_pose > 0)
    Status(o, cv::format("%d frame(s) without a pose in %s skipped", without_pose, rawlog.c_str()));
  if (frames.empty())
    throw std::invalid_argument(
        rawlog + ": no frame of the phases has a pose" +
        (o.poses_from_rawlog ? " (--poses rawlog: run novelty-poses on it first)" : ""));
  illumination::IlluminationMap map(o.map);
  // Each lighting's frames as reference views: the baselines' references are rendered from them.
  std::vector<std::vector<views::ReferenceView>> sequences(train.size());
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t m = 0; m < train.size(); ++m) {
    map.BeginLighting();
    for (int i = train[m]->first; i <= train[m]->last; ++i) {
      if (!frames.count(i)) continue;
      map.AddTrainingFrame(frames[i]);
      sequences[m].push_back(views::ReferenceViewOf(frames[i]));
    }
    if (sequences[m].empty())
      throw std::invalid_argument(rawlog + ": no frame of phase '" + train[m]->name + "'");
    Progress(o, "lightings", int(m + 1), int(train.size()));
  }
  Status(o, "invariant images at the viewpoints ...");
  map.Build();
  const double learn_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  double coverage = 0.0;
  for (int v = 0; v < map.size(); ++v) coverage += map.model(v).coverage / map.size();
  Status(o, cv::format("%d viewpoints (%d dropped), mean coverage %.1f %%, %.1f MB, %.1f s",
                       map.size(), map.dropped_viewpoints(), 100 * coverage, map.BytesUsed() / 1e6,
                       learn_seconds));
  std::vector<std::vector<Eigen::Isometry3d>> poses(train.size());
  for (std::size_t m = 0; m < train.size(); ++m)
    for (const auto& v : sequences[m]) poses[m].push_back(v.T_world_cam);
  views::DepthMeshWarper warper(o.map.synthesis.warp, views::WarpOutputsFor(o.map.synthesis.blend));
  double frame_coverage = 0.0;
  for (int i = test.first; i <= test.last; ++i) {
    if (!frames.count(i)) continue;
    const core::Frame& f = frames[i];
    TestFrame t;
    t.index = i;
    t.image = f.rgb;
    t.truth = NoveltyTruth(truth, i, t.image.size());
    const auto t0 = std::chrono::steady_clock::now();
    const illumination::IlluminationMapResult r = map.Detect(f);
    e.detect_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    frame_coverage += r.coverage;
    t.evaluated =
        r.coverage > 0.0 ? r.viewpoint.covered.clone() : cv::Mat::zeros(t.image.size(), CV_8UC1);
    t.novelty = r.coverage > 0.0 ? r.novelty.novelty : cv::Mat::zeros(t.image.size(), CV_32F);
    t.invariant = r.coverage > 0.0
                      ? illumination::LinearImage8(r.viewpoint.log_invariant, r.viewpoint.covered)
                      : cv::Mat::zeros(t.image.size(), CV_8UC3);
    // Each sequence's virtual image at this pose: the first is the baselines' reference.
    for (std::size_t m = 0; m < train.size(); ++m) {
      const views::SynthesisResult s =
          views::SynthesiseSelected(warper, sequences[m], poses[m], f.camera, *f.T_world_cam,
                                    o.map.selection, o.map.synthesis);
      // Where the reference has no view, the observation stands in: the baselines' blocks
      // (NGC's reach ~10 px on three layers) would otherwise compare against black next to
      // holes; those pixels are not scored.
      cv::Mat reference = s.rgb.clone();
      t.image.copyTo(reference, ~s.valid);
      t.references.push_back(reference);
      t.evaluated &= s.valid;
    }
    Score(t, e, report, dir);
    Progress(o, "test frames", e.tested, test.last - test.first + 1);
  }
  learnt.summary =
      cv::format("%zu lightings, %d viewpoints (%d dropped), mean viewpoint coverage %.1f %%",
                 train.size(), map.size(), map.dropped_viewpoints(), 100 * coverage);
  learnt.decision_threshold = map.decision_threshold();
  learnt.findings = {{"lightings", std::to_string(train.size())},
                     {"viewpoints", std::to_string(map.size())},
                     {"viewpoints dropped", std::to_string(map.dropped_viewpoints())},
                     {"mean viewpoint coverage", eval::PercentText(coverage)},
                     {"mean test-frame coverage of the interpolated invariant image",
                      eval::PercentText(frame_coverage / std::max(1, e.tested))},
                     {"frames with the ground truth's depth", std::to_string(depth_from_truth)},
                     {"camera poses", o.poses_from_rawlog ? "rawlog" : "ground truth"},
                     {"frames skipped without a pose", std::to_string(without_pose)},
                     {"map MB", cv::format("%.1f", map.BytesUsed() / 1e6)}};
  return learn_seconds;
}

}  // namespace

IlluminationExperimentResult RunIlluminationExperiment(const IlluminationExperimentOptions& o,
                                                       const std::string& out_dir) {
  const sim::GroundTruthReader truth(o.groundtruth);
  if (o.train_phases.empty()) throw std::invalid_argument("no training phase named");
  std::vector<const sim::GroundTruthReader::Phase*> train;
  for (const std::string& name : o.train_phases) train.push_back(&FindPhase(truth, name));
  const auto& test = FindPhase(truth, o.test_phase);

  const fs::path dir = out_dir;
  fs::create_directories(dir / "panels");
  eval::HtmlReport report("novelty-illumination: " + o.rawlog);
  Evaluation e;
  LearntSummary learnt;
  const bool moving = train.size() > 1;
  const double learn_seconds =
      moving ? RunMoving(o.rawlog, truth, train, test, o, dir, report, e, learnt)
             : RunStatic(o.rawlog, truth, *train.front(), test, o.reference_frame, o, dir, report,
                         e, learnt);
  if (e.tested == 0)
    throw std::invalid_argument("no test frame of phase '" + test.name + "' in " + o.rawlog);
  const long positives = std::count(e.positive.begin(), e.positive.end(), true);
  if (positives == 0 || positives == long(e.positive.size()))
    throw std::invalid_argument(
        "phase '" + test.name + "': " + std::to_string(e.positive.size()) + " scored pixels, " +
        std::to_string(positives) +
        " of them changed; a ROC needs both (the map or the references cover too little, or "
        "nothing changed: novelty-illumination-map gives a pass without novelty its false-alarm "
        "rate)");
  return Finish(e, learnt, o.map.threshold.false_alarm_rate,
                moving ? "lightings" : "training frames", learn_seconds, dir, report);
}

}  // namespace novelty::experiments
