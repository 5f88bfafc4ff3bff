#include "experiments/surprise_experiment.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/maps/CMultiMetricMap.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/frame_stem.h"
#include "core/write_rgb_image.h"
#include "eval/attentional_selectivity.h"
#include "eval/findings_report.h"
#include "eval/first_run.h"
#include "eval/html_report.h"
#include "eval/novelty_panel.h"
#include "eval/object_steps_csv.h"
#include "eval/prediction_quality.h"
#include "eval/selectivity_csv.h"
#include "eval/selectivity_findings.h"
#include "eval/skipped_frames.h"
#include "experiments/maps_config.h"
#include "maps/appearance/appearance_map.h"
#include "maps/appearance/differencing_map.h"
#include "mrpt_plugins/c_appearance_map.h"
#include "mrpt_plugins/c_differencing_map.h"
#include "mrpt_plugins/c_object_database_map.h"
#include "mrpt_plugins/multi_map_config.h"
#include "mrpt_plugins/option_table.h"
#include "mrpt_plugins/rawlog_map_player.h"
#include "sim/output/ground_truth_reader.h"

namespace novelty::experiments {

std::vector<double> ParseViewFactors(const std::string& list) {
  std::vector<double> factors;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');) {
    std::size_t used = 0;
    double f = 0.0;
    try {
      f = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || !(f >= 1.0) || !std::isfinite(f))
      throw std::invalid_argument("--compare-views: '" + item + "' is not a finite factor >= 1");
    factors.push_back(f);
  }
  // Each factor is a pair of maps as large as the main ones, and a row of every metric.
  constexpr std::size_t kMaxFactors = 8;
  if (factors.size() > kMaxFactors)
    throw std::invalid_argument("--compare-views: " + std::to_string(factors.size()) +
                                " factors, at most " + std::to_string(kMaxFactors));
  return factors;
}

namespace {

// The maps the run feeds: the CAppearanceMap of the .ini and its CDifferencingMap if it declares
// one (the baseline surprise is scored against), then, per compare_views factor, copies of their
// definitions with reference views that many times sparser (fig. 4.13's R2, R4), all in one
// CMultiMetricMap.
struct RunMaps {
  mrpt::maps::CMultiMetricMap multi;
  std::vector<double> sparser_factors;
  std::vector<std::vector<eval::SelectivityRow>> sparser_rows;

  RunMaps(const mrpt::config::CConfigFileBase& ini, const std::string& source, double reduction,
          const std::vector<double>& factors)
      : sparser_factors(factors), sparser_rows(factors.size()) {
    mrpt::maps::TSetOfMetricMapInitializers inits =
        mrpt_plugins::LoadMultiMapConfig(ini, "map", source, {"CAppearanceMap"});
    std::shared_ptr<mrpt_plugins::CAppearanceMap::TMapDefinition> appearance;
    std::vector<std::shared_ptr<mrpt_plugins::CDifferencingMap::TMapDefinition>> differencing;
    for (auto& def : inits) {
      if (auto a = std::dynamic_pointer_cast<mrpt_plugins::CAppearanceMap::TMapDefinition>(def))
        appearance = a;
      if (auto d = std::dynamic_pointer_cast<mrpt_plugins::CDifferencingMap::TMapDefinition>(def))
        differencing.push_back(d);
    }
    if (differencing.size() > 1)
      throw std::runtime_error(source + ": [map] declares " + std::to_string(differencing.size()) +
                               " CDifferencingMap, the run compares with one (0 or 1)");
    appearance->config.map.views.new_view_distance *= reduction;
    if (!differencing.empty()) differencing[0]->config.map.new_view_distance *= reduction;
    for (const double f : factors) {
      auto a = *appearance;
      a.config.map.views.new_view_distance *= f;
      inits.push_back(a);
      if (differencing.empty()) continue;
      auto d = *differencing[0];
      d.config.map.new_view_distance *= f;
      inits.push_back(d);
    }
    multi.setListOfMaps(inits);
    mrpt_plugins::LinkObjectDatabaseMaps(multi);  // an object database reads the appearance map
  }

  mrpt_plugins::CAppearanceMap& appearance(std::size_t k = 0) const {
    return *multi.mapByClass<mrpt_plugins::CAppearanceMap>(k);
  }
  /// The differencing map's products, null when the .ini declares none.
  const appearance::DifferencingProducts* differencing(std::size_t k = 0) const {
    const auto d = multi.mapByClass<mrpt_plugins::CDifferencingMap>(k);
    return d ? &d->lastProducts() : nullptr;
  }
  bool has_differencing() const { return differencing() != nullptr; }
  /// Whether the appearance and differencing maps, sparser ones too, learn from what they judge.
  void SetLearning(bool on) {
    for (const auto& m : multi.maps) {
      if (auto a = std::dynamic_pointer_cast<mrpt_plugins::CAppearanceMap>(m)) a->setLearning(on);
      if (auto d = std::dynamic_pointer_cast<mrpt_plugins::CDifferencingMap>(m)) d->setLearning(on);
    }
  }
  /// The object database, if the .ini declares one.
  mrpt_plugins::CObjectDatabaseMap* objects() const {
    return multi.mapByClass<mrpt_plugins::CObjectDatabaseMap>().get();
  }
};

// The findings of thesis 4.3 for the glass-and-cup scenario, each read over the first run of its
// phase (Q1 → Q2, found from the true camera positions). Phases or regions a sequence lacks are
// left out.
std::vector<eval::Finding> ThesisFindings(const std::vector<sim::GroundTruthReader::Phase>& phases,
                                          const std::map<int, Eigen::Isometry3d>& poses) {
  std::map<int, Eigen::Vector3d> positions;
  for (const auto& [frame, pose] : poses) positions[frame] = pose.translation();
  const struct {
    const char* phase;
    const char* region;
    eval::Claim claim;
    const char* what;
  } specs[] = {
      {"B", "glass", eval::Claim::kSurpriseMoreSelective,
       "glass: surprise more selective than differencing (fig. 4.9)"},
      {"C", "cup", eval::Claim::kBothDetect, "black cup: detected by both, PAS > 0 dB (fig. 4.12)"},
      {"D", "removed", eval::Claim::kSurpriseLessSelective,
       "removed cup: less surprising than differencing makes it (fig. 4.12, phase D)"}};
  std::vector<eval::Finding> findings;
  for (const auto& spec : specs) {
    for (const auto& p : phases) {
      if (p.name != spec.phase || !positions.count(p.first)) continue;
      findings.push_back({spec.what, spec.region, spec.claim, p.first,
                          eval::FirstRunEnd(positions, p.first, p.last)});
    }
  }
  return findings;
}

// What a run gathered for the report.
struct Played {
  std::vector<eval::SelectivityRow> rows;
  std::vector<int> panel_frames;
  int frames = 0;
  double seconds = 0.0;
  double warp_sigma_sum = 0.0;   // the appearance map's floor s (px), summed over frames
  double aligned_deg_sum = 0.0;  // align_to_prior: the rotations applied (deg), summed
  int aligned_frames = 0;
  std::vector<int> judged;  // frame numbers, with how well each was predicted
  std::vector<eval::PredictionQuality> prediction;
};

// The prediction's quality per frame in the report: a sentence of medians and two plots.
void ReportPrediction(const Played& run, eval::HtmlReport& report) {
  const eval::PredictionSummary m = eval::SummarisePrediction(run.prediction);
  if (m.frames == 0) return;
  report.Heading("Prediction (frames.csv)");
  report.Paragraph(cv::format(
      "Over the %d frames the map predicted: median coverage %.1f %% of the pixels, PSNR of the "
      "expected image %.1f dB over them, surprise %.2f nats mean and %.2f nats at the 95th "
      "percentile (on an unchanged scene: the false-surprise level).",
      m.frames, 100 * m.median_coverage, m.median_psnr_db, m.median_mean_surprise,
      m.median_p95_surprise));
  eval::PlotSeries psnr{"PSNR of the expected image", "#0072b2", {}, 1.0},
      coverage{"coverage (%)", "#009e73", {}, 1.0}, mean{"mean surprise", "#c0392b", {}, 1.0},
      p95{"95th percentile", "#cc79a7", {}, 1.0};
  for (std::size_t k = 0; k < run.prediction.size(); ++k) {
    const double f = run.judged[k];
    const eval::PredictionQuality& q = run.prediction[k];
    psnr.points.push_back({f, q.psnr_db});
    coverage.points.push_back({f, 100 * q.coverage});
    mean.points.push_back({f, q.mean_surprise});
    p95.points.push_back({f, q.p95_surprise});
  }
  report.Raw(
      eval::SvgLinePlot("Expected image against the frame", "frame", "dB, %", {psnr, coverage}));
  report.Raw(eval::SvgLinePlot("Surprise over the predicted pixels", "frame", "nats", {mean, p95}));
}

void WriteReport(const std::string& out, const Played& run,
                 const std::vector<sim::GroundTruthReader::Phase>& phases,
                 const std::vector<eval::Finding>& findings, const RunMaps& maps, int views,
                 const std::vector<std::string>& notes, const std::string& verdict,
                 std::ostream* console) {
  const std::vector<eval::SelectivityRow>& rows = run.rows;
  eval::HtmlReport report(maps.has_differencing()
                              ? "NoveltyMaps — Bayesian surprise vs image differencing"
                              : "NoveltyMaps — Bayesian surprise");
  char summary[256];
  std::snprintf(summary, sizeof summary,
                "%d frames in %.1f s (%.1f frames/s); %d reference views in the map at the end.",
                run.frames, run.seconds, run.frames / run.seconds, views);
  report.Paragraph(summary);
  report.Paragraph(verdict);
  for (const std::string& note : notes) report.Paragraph(note);
  ReportPrediction(run, report);
  std::ofstream csv(out + "/findings.csv");
  if (console && !findings.empty())
    *console << "Findings of thesis 4.3 (surprise vs differencing, first run after each change):\n";
  eval::FindingsReport findings_report(csv, console);
  findings_report.AddFindings(rows, findings, report);
  std::vector<eval::SparserRun> sparser_runs;
  for (std::size_t k = 0; k < maps.sparser_factors.size(); ++k)
    sparser_runs.push_back({maps.sparser_factors[k], maps.appearance(k + 1).map().store().size(),
                            &maps.sparser_rows[k]});
  findings_report.AddSparser(rows, views, sparser_runs, findings, report);
  std::vector<eval::PlotBand> bands;
  for (const auto& p : phases) bands.push_back({double(p.first), double(p.last), p.name});
  std::set<std::string> regions;
  for (const eval::SelectivityRow& r : rows) regions.insert(r.region);
  for (const std::string& region : regions) {
    report.Heading("Region: " + region);
    // One point per frame that shows the region: no line across frames where it is not visible.
    eval::PlotSeries as_s{"AS surprise", "#c0392b", {}, 1.0},
        as_d{"AS differencing", "#2471a3", {}, 1.0};
    eval::PlotSeries pas_s{"PAS surprise", "#c0392b", {}, 1.0},
        pas_d{"PAS differencing", "#2471a3", {}, 1.0};
    for (const eval::SelectivityRow& r : rows) {
      if (r.region != region) continue;
      as_s.points.push_back({double(r.frame), r.surprise.as_db});
      as_d.points.push_back({double(r.frame), r.difference.as_db});
      pas_s.points.push_back({double(r.frame), r.surprise.pas_db});
      pas_d.points.push_back({double(r.frame), r.difference.pas_db});
    }
    report.Raw(eval::SvgLinePlot("Attentional selectivity (eq. 4.24) — " + region, "frame", "dB",
                                 {as_s, as_d}, bands));
    report.Raw(eval::SvgLinePlot("Peak attentional selectivity (eq. 4.25) — " + region, "frame",
                                 "dB", {pas_s, pas_d}, bands));
    std::vector<std::vector<std::string>> table;
    for (const auto& p : phases) {
      const eval::MeanSelectivity m = eval::MeanOver(rows, region, p.first, p.last);
      if (m.frames == 0) continue;
      std::vector<std::string> line = {p.name};
      for (const std::string& cell : eval::MeanCells(m)) line.push_back(cell);
      line.push_back(m.as_surprise > m.as_difference ? "surprise" : "differencing");
      table.push_back(line);
    }
    report.Table({"phase", "frames", "mean AS surprise", "mean AS differencing",
                  "mean PAS surprise", "mean PAS differencing", "coverage", "higher AS"},
                 table);
  }
  report.Heading(std::string("Panels: camera | expected (τ) | surprise | uncertainty Σβ") +
                 (maps.has_differencing() ? " | differencing" : ""));
  for (int f : run.panel_frames)
    report.Image("panels/" + core::FrameStem(f) + ".png", "frame " + std::to_string(f));
  report.Save(out + "/report.html");
}

// Plays the rawlog into the maps; per frame the selectivity of every changed region (metrics.csv,
// and the sparser maps' rows), every K-th panel, progress through the options' callback.
Played Play(const SurpriseExperimentOptions& a, const std::string& out, RunMaps& maps,
            const sim::GroundTruthReader* ground_truth, mrpt_plugins::RawlogMapPlayer& player) {
  mrpt_plugins::CAppearanceMap& map = maps.appearance();
  eval::SelectivityCsv csv(out + "/metrics.csv");
  std::optional<eval::ObjectStepsCsv> object_steps;
  if (maps.objects()) object_steps.emplace(out + "/objects.csv");
  int objects_used = 0;  // frames the object database took so far
  // What a frame's number decides, decided for the frame actually inserted.
  player.SetBeforeInsert([&](int frame) {
    if (maps.objects()) maps.objects()->setPaused(frame < a.objects_from);
    maps.SetLearning(a.learn_until == 0 || frame <= a.learn_until);
  });
  Played run;
  int index = 0;
  const auto start = std::chrono::steady_clock::now();
  // Without ground truth the rawlog's length is not known before it is read (0: unknown).
  const int poses = ground_truth ? int(ground_truth->CameraPoses().size()) : 0;
  const int total = a.max_frames ? (poses ? std::min(*a.max_frames, poses) : *a.max_frames) : poses;
  while ((!a.max_frames || run.frames < *a.max_frames) && player.Next(maps.multi, index)) {
    const appearance::AppearanceProducts& p = map.lastProducts();
    const appearance::DifferencingProducts* d = maps.differencing();
    ++run.frames;
    run.judged.push_back(index);
    run.prediction.push_back(eval::MeasurePrediction(map.lastFrame().rgb, p.expected_rgb, p.valid,
                                                     p.surprise, a.verdict.tail_pixels));
    if (object_steps && maps.objects()->framesUsed() != objects_used) {
      objects_used = maps.objects()->framesUsed();
      object_steps->Add(index, maps.objects()->lastStep(), maps.objects()->database().features());
    }
    const auto regions =
        ground_truth ? ground_truth->ChangedRegions(index, 30) : std::map<std::string, cv::Mat>{};
    for (const auto& [object, region] : regions) {
      run.rows.push_back({index, object, eval::AttentionalSelectivity(p.surprise, region),
                          eval::AttentionalSelectivity(d->difference, region)});
      csv.Add(run.rows.back(), ground_truth->PhaseOf(index));
      for (std::size_t k = 0; k < maps.sparser_factors.size(); ++k) {
        maps.sparser_rows[k].push_back(
            {index, object,
             eval::AttentionalSelectivity(maps.appearance(k + 1).lastProducts().surprise, region),
             eval::AttentionalSelectivity(maps.differencing(k + 1)->difference, region)});
      }
    }
    if (index % a.panels_every == 0) {
      const std::string stem = core::FrameStem(index);
      core::WriteRgbImage(out + "/panels/" + stem + ".png",
                          eval::NoveltyPanel(map.lastFrame().rgb, p, d, stem));
      run.panel_frames.push_back(index);
    }
    run.warp_sigma_sum += p.warp_sigma_px;
    if (!p.aligned_rotation.isZero()) {
      run.aligned_deg_sum += p.aligned_rotation.norm() * 180.0 / M_PI;
      ++run.aligned_frames;
    }
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (a.progress) a.progress(index, total);
  }
  return run;
}

// Skipped frames in one line (one line per frame can be thousands) for the status callback and
// as a note for the report; an early end of the rawlog too.
std::vector<std::string> SkipNotes(const SurpriseExperimentOptions& o,
                                   const mrpt_plugins::RawlogMapPlayer& player, int frames) {
  const auto& reasons = player.skip_reasons();
  std::vector<std::string> notes;
  if (!reasons.empty()) {
    notes.push_back(eval::SkippedFramesSummary(frames + int(reasons.size()), reasons));
    if (o.status) o.status(notes.back());
  }
  if (!player.stopped_by().empty()) {
    notes.push_back("The rawlog ends early: " + player.stopped_by() + ". Results cover the " +
                    std::to_string(frames) + " frames read.");
    if (o.status) o.status(notes.back());
  }
  return notes;
}

}  // namespace

SurpriseExperimentResult RunSurpriseExperiment(const SurpriseExperimentOptions& a,
                                               const std::string& out) {
  if (!(a.view_reduction >= 1.0)) throw std::invalid_argument("view_reduction must be >= 1");
  if (a.panels_every < 1) throw std::invalid_argument("panels_every must be >= 1");
  if (a.objects_from < 1) throw std::invalid_argument("objects_from must be >= 1");
  if (a.learn_until < 0) throw std::invalid_argument("learn_until must be >= 0");
  if (a.max_frames && *a.max_frames < 1) throw std::invalid_argument("max_frames must be >= 1");
  a.verdict.Check();
  const MapsConfig config = OpenMapsConfig(a.config);
  RunMaps maps(*config.ini, config.source, a.view_reduction, a.compare_views);
  mrpt_plugins::CAppearanceMap& map = maps.appearance();
  if (!a.map_in.empty()) {
    map.LoadFromFile(a.map_in);
    if (a.status)
      a.status("continuing " + a.map_in +
               " with the options saved in it (the .ini's options and the view reduction apply "
               "to the other maps)");
  }
  if (!a.objects_in.empty()) {
    if (!maps.objects())
      throw std::invalid_argument(
          a.objects_in + ": " +
          (a.config.empty() ? "the default maps hold" : a.config + " declares") +
          " no CObjectDatabaseMap to load it into");
    maps.objects()->LoadFromFile(a.objects_in);
    if (a.status)
      a.status("object database from " + a.objects_in +
               ", with the options saved in it (the .ini's CObjectDatabaseMap options do not "
               "apply)");
  }
  // Scored only where there is ground truth; the run itself needs none.
  std::optional<sim::GroundTruthReader> ground_truth;
  if (!a.groundtruth.empty()) ground_truth.emplace(a.groundtruth);
  if (ground_truth && !maps.has_differencing())
    throw std::invalid_argument(
        "ground truth scores surprise against image differencing (thesis 4.3), but " +
        (a.config.empty() ? std::string("the default maps declare") : a.config + " declares") +
        " no CDifferencingMap");
  const mrpt_plugins::PoseSource pose_source = mrpt_plugins::ParsePoseSource(a.pose_source);
  if (pose_source == mrpt_plugins::PoseSource::kGroundTruth && !ground_truth)
    throw std::invalid_argument(
        "poses from the ground truth need its folder; without one take the rawlog's poses "
        "(--poses rawlog: novelty-import and novelty-poses write them) or its odometry");
  std::filesystem::create_directories(out + "/panels");
  if (const auto parent = std::filesystem::path(a.map_out).parent_path(); !parent.empty())
    std::filesystem::create_directories(parent);
  mrpt_plugins::RawlogMapPlayer player(
      a.rawlog, pose_source,
      ground_truth ? ground_truth->CameraPoses() : std::map<int, Eigen::Isometry3d>{});
  const Played run = Play(a, out, maps, ground_truth ? &*ground_truth : nullptr, player);
  if (run.frames == 0) {  // nothing to report, and a saved map must not be replaced by an empty one
    const auto& reasons = player.skip_reasons();
    const std::string hint =
        pose_source == mrpt_plugins::PoseSource::kRawlog && !reasons.empty()
            ? "; --poses rawlog needs pose observations: novelty-import and novelty-poses write "
              "them; a simulator's rawlog: --groundtruth DIR"
            : "";
    throw std::runtime_error(a.rawlog + ": no frame was inserted into the maps (" +
                             (reasons.empty() ? std::string("no camera observation")
                                              : eval::SkippedFramesSummary(0, reasons)) +
                             hint + ")");
  }
  SurpriseExperimentResult r;
  r.notes = SkipNotes(a, player, run.frames);
  if (!ground_truth)
    r.notes.push_back("No ground truth given: products, panels and the map; nothing is scored.");
  const std::vector<sim::GroundTruthReader::Phase> phases =
      ground_truth ? ground_truth->Phases() : std::vector<sim::GroundTruthReader::Phase>{};
  r.verdict = eval::JudgeNovelty(run.judged, run.prediction, a.verdict);
  r.verdict_sentence = r.verdict.Sentence();
  WriteReport(out, run, phases,
              ground_truth ? ThesisFindings(phases, ground_truth->CameraPoses())
                           : std::vector<eval::Finding>{},
              maps, map.map().store().size(), r.notes, r.verdict_sentence, a.console);
  eval::WritePredictionCsv(out + "/frames.csv", run.judged, run.prediction);
  r.prediction = eval::SummarisePrediction(run.prediction);
  if (!a.map_out.empty()) map.SaveToFile(a.map_out);
  map.SaveSceneFile(out + "/map.3Dscene");  // for SceneViewer3D
  if (const mrpt_plugins::CObjectDatabaseMap* objects = maps.objects()) {
    objects->SaveToFile(out + "/map.object_database");
    r.objects_summary = objects->asString();
  }
  r.frames = run.frames;
  r.skipped = player.skipped();
  r.seconds = run.seconds;
  r.ended_early = !player.stopped_by().empty();
  r.map_summary = map.asString();
  r.views = map.map().store().size();
  r.rows = run.rows;
  if (run.warp_sigma_sum > 0.0) r.mean_warp_sigma_px = run.warp_sigma_sum / run.frames;
  r.aligned_frames = run.aligned_frames;
  if (run.aligned_frames > 0) r.mean_aligned_deg = run.aligned_deg_sum / run.aligned_frames;
  return r;
}

std::string SurpriseRunSummary(const SurpriseExperimentResult& r, const std::string& out,
                               const std::string& map_out) {
  std::string s;
  if (!r.objects_summary.empty())
    s += cv::format("  objects: %s/objects.csv, %s/map.object_database\n  %s\n", out.c_str(),
                    out.c_str(), r.objects_summary.c_str());
  s += cv::format(
      "%d frames (%d skipped) in %.1f s\n  metrics: %s/metrics.csv\n"
      "  map:     %s (%s)\n  report:  %s/report.html\n",
      r.frames, r.skipped, r.seconds, out.c_str(), map_out.c_str(), r.map_summary.c_str(),
      out.c_str());
  if (r.prediction.frames > 0)
    s += cv::format(
        "  predicted: median coverage %.1f %%, PSNR of the expected image %.1f dB, surprise "
        "%.2f nats (95th percentile %.2f) — %s/frames.csv\n",
        100 * r.prediction.median_coverage, r.prediction.median_psnr_db,
        r.prediction.median_mean_surprise, r.prediction.median_p95_surprise, out.c_str());
  if (r.mean_warp_sigma_px > 0.0)
    s += cv::format("  warp-error floor: s = %.2f px on average over the frames\n",
                    r.mean_warp_sigma_px);
  if (r.aligned_frames > 0)
    s += cv::format("  aligned to the prior: %d frames, by %.3f deg on average\n", r.aligned_frames,
                    r.mean_aligned_deg);
  return s + "  " + r.verdict_sentence + "\n";
}

}  // namespace novelty::experiments
