// novelty-run: the surprise pipeline (thesis ch. 4) over an RGB-D rawlog.
//
//   novelty-run --rawlog DIR/<name>.rawlog --groundtruth DIR/groundtruth --out OUT
//               [--config share/novelty_run.ini] [--frames N] [--panels-every K]
//               [--poses groundtruth|rawlog|odometry] [--compare-views 2,4]
//
// Runs as an MRPT program would: a CMultiMetricMap built from the .ini (a CAppearanceMap and a
// CDifferencingMap declared there), every camera observation of the rawlog passed to its
// insertObservation with the robot pose — from the ground truth, from the CObservationRobotPose
// that novelty-poses put into the rawlog (depth may come from novelty-depth), or from wheel
// odometry — and the products read back from the maps. It writes
//   OUT/panels/NNNNNN.png  camera | expected | surprise | uncertainty | differencing
//   OUT/metrics.csv        frame,phase,object,AS_surprise,PAS_surprise,AS_diff,PAS_diff,coverage
//                          (share of pixels with a prediction, which AS is measured over) for every
//                          changed object in view (regions from the ground-truth novelty masks:
//                          added objects and the arm by id, "removed" where objects were taken)
//   OUT/findings.csv       the findings of thesis 4.3, each over the first run after its change,
//                          with its numbers and whether it holds (fig. 4.13 too with
//                          --compare-views: maps with sparser reference views run side by side)
//   OUT/report.html        the findings, plots of AS/PAS over frames, a table per object and
//                          phase, panels,
// and the map (OUT/map.appearance_map, or --map-out; --map-in continues from a saved map) with
// its reference-view frusta as OUT/map.3Dscene for SceneViewer3D. With a CObjectDatabaseMap in
// the .ini (thesis ch. 5, share/object_database.ini) also
//   OUT/objects.csv        per frame its focus box, added/removed, features, recognition
//                          (from --objects-from on: the appearance map learns the room first)
//   OUT/map.object_database  the learnt database (--objects-in starts from a saved one: learnt
//                          in one room, recognised in another).
// Progress on stderr.
//
// Exit status: 0 done; 1 an error (one line on stderr; nothing overwritten, no map saved when no
// frame was inserted); 2 bad command line; 3 the rawlog ends early (cut short or corrupt): the
// results and the map cover the frames read, and stderr names where it ended.
#include <tclap/CmdLine.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <set>
#include <sstream>

#include "apps/command_line.h"
#include "apps/shell/output_folder.h"
#include "apps/shell/program.h"
#include "apps/shell/progress.h"
#include "apps/shell/skipped_frames.h"
#include "core/frame_stem.h"
#include "core/same_file.h"
#include "core/write_rgb_image.h"
#include "eval/attentional_selectivity.h"
#include "eval/findings_report.h"
#include "eval/first_run.h"
#include "eval/html_report.h"
#include "eval/novelty_panel.h"
#include "eval/object_steps_csv.h"
#include "eval/selectivity_csv.h"
#include "eval/selectivity_findings.h"
#include "maps/appearance/appearance_map.h"
#include "maps/appearance/differencing_map.h"
#include "mrpt_plugins/c_appearance_map.h"
#include "mrpt_plugins/c_differencing_map.h"
#include "mrpt_plugins/c_object_database_map.h"
#include "mrpt_plugins/multi_map_config.h"
#include "mrpt_plugins/option_table.h"
#include "mrpt_plugins/rawlog_map_player.h"
#include "sensors/rawlog/brief_message.h"
#include "sim/output/ground_truth_reader.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>

namespace {

using namespace novelty;

// "2,4" → {2, 4}; each factor must be ≥ 1.
std::vector<double> ParseFactors(const std::string& list) {
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

// The maps declared when no --config is given: one of each, every option at its default
// (share/novelty_run.ini is the same, with the keys documented).
constexpr const char* kDefaultMaps = R"(
[map]
CAppearanceMap_count = 1
CDifferencingMap_count = 1
)";

// The maps novelty-run feeds: the first CAppearanceMap and CDifferencingMap of the .ini, then,
// per --compare-views factor, copies of their definitions with reference views that many times
// sparser (fig. 4.13's R2, R4), all in one CMultiMetricMap.
struct RunMaps {
  mrpt::maps::CMultiMetricMap multi;
  std::vector<double> sparser_factors;
  std::vector<std::vector<eval::SelectivityRow>> sparser_rows;

  RunMaps(const mrpt::config::CConfigFileBase& ini, const std::string& source, double reduction,
          const std::vector<double>& factors)
      : sparser_factors(factors), sparser_rows(factors.size()) {
    // The sparser maps are copies of the one appearance and one differencing map.
    mrpt::maps::TSetOfMetricMapInitializers inits = mrpt_plugins::LoadMultiMapConfig(
        ini, "map", source, {"CAppearanceMap", "CDifferencingMap"});
    // CheckMultiMapConfig made these exactly one each.
    std::shared_ptr<mrpt_plugins::CAppearanceMap::TMapDefinition> appearance;
    std::shared_ptr<mrpt_plugins::CDifferencingMap::TMapDefinition> differencing;
    for (auto& def : inits) {
      if (auto a = std::dynamic_pointer_cast<mrpt_plugins::CAppearanceMap::TMapDefinition>(def))
        appearance = a;
      if (auto d = std::dynamic_pointer_cast<mrpt_plugins::CDifferencingMap::TMapDefinition>(def))
        differencing = d;
    }
    appearance->config.map.views.new_view_distance *= reduction;
    differencing->config.map.new_view_distance *= reduction;
    for (const double f : factors) {
      auto a = *appearance;
      a.config.map.views.new_view_distance *= f;
      auto d = *differencing;
      d.config.map.new_view_distance *= f;
      inits.push_back(a);
      inits.push_back(d);
    }
    multi.setListOfMaps(inits);
    mrpt_plugins::LinkObjectDatabaseMaps(multi);  // an object database reads the appearance map
  }

  mrpt_plugins::CAppearanceMap& appearance(std::size_t k = 0) const {
    return *multi.mapByClass<mrpt_plugins::CAppearanceMap>(k);
  }
  mrpt_plugins::CDifferencingMap& differencing(std::size_t k = 0) const {
    return *multi.mapByClass<mrpt_plugins::CDifferencingMap>(k);
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

void WriteReport(const std::string& out, const std::vector<eval::SelectivityRow>& rows,
                 const std::vector<sim::GroundTruthReader::Phase>& phases,
                 const std::vector<eval::Finding>& findings, const RunMaps& maps,
                 const std::vector<int>& panel_frames, int frames, double seconds, int views,
                 const std::vector<std::string>& notes) {
  eval::HtmlReport report("NoveltyMaps — Bayesian surprise vs image differencing");
  char summary[256];
  std::snprintf(summary, sizeof summary,
                "%d frames in %.1f s (%.1f frames/s); %d reference views in the map at the end.",
                frames, seconds, frames / seconds, views);
  report.Paragraph(summary);
  for (const std::string& note : notes) report.Paragraph(note);
  std::ofstream csv(out + "/findings.csv");
  eval::FindingsReport findings_report(csv, &std::cout);
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
  report.Heading("Panels: camera | expected (τ) | surprise | uncertainty Σβ | differencing");
  for (int f : panel_frames)
    report.Image("panels/" + core::FrameStem(f) + ".png", "frame " + std::to_string(f));
  report.Save(out + "/report.html");
}

// What the command line asks for.
struct RunArgs {
  std::string rawlog, truth, out, config, map_in, map_out, compare_views, objects_in;
  std::optional<int> max_frames;
  int panels_every = 10;
  int objects_from = 1;
  std::string pose_source = "groundtruth";
  double reduction = 1.0;
};

// Parses and checks the command line; throws TCLAP::ArgException or std::invalid_argument.
RunArgs ParseArgs(int argc, char** argv) {
  novelty::apps::CommandLine cmd(
      "Bayesian surprise with the probabilistic appearance map over an RGB-D "
      "rawlog, against image differencing, through MRPT's CMultiMetricMap.",
      "0.1");
  TCLAP::ValueArg<std::string> rawlog("", "rawlog", "RGB-D rawlog", true, "", "R.rawlog", cmd);
  TCLAP::ValueArg<std::string> truth("", "groundtruth", "Ground-truth folder (poses, masks)", true,
                                     "", "DIR", cmd);
  TCLAP::ValueArg<std::string> out("", "out", "Output folder", true, "", "OUT", cmd);
  TCLAP::ValueArg<std::string> config(
      "", "config",
      "The maps as a CMultiMetricMap .ini (section [map]: CAppearanceMap_count, "
      "CDifferencingMap_count; options in [map_CAppearanceMap_00_options] ...), e.g. "
      "share/novelty_run.ini; default: both maps with default options",
      false, "", "INI", cmd);
  TCLAP::ValueArg<int> max_frames("", "frames", "Stop after N frames inserted into the maps", false,
                                  0, "N", cmd);
  TCLAP::ValueArg<int> panels_every("", "panels-every", "Write every K-th panel (default 10)",
                                    false, 10, "K", cmd);
  TCLAP::ValueArg<std::string> map_in("", "map-in", "Continue from a saved appearance map", false,
                                      "", "M", cmd);
  TCLAP::ValueArg<std::string> map_out(
      "", "map-out", "Save the appearance map here (default OUT/map.appearance_map)", false, "",
      "M", cmd);
  TCLAP::ValueArg<std::string> objects_in(
      "", "objects-in",
      "Start the CObjectDatabaseMap (declared in --config) from a saved object database", false, "",
      "D", cmd);
  TCLAP::ValueArg<int> objects_from(
      "", "objects-from",
      "The CObjectDatabaseMap takes frames from this one on (default 1); before, the appearance "
      "map learns the room alone (the thesis's I1: 361 for share/scenarios/object_learning.scn; "
      "a frame skipped just before it delays the start by one)",
      false, 1, "N", cmd);
  std::vector<std::string> pose_sources = {"groundtruth", "rawlog", "odometry"};
  TCLAP::ValuesConstraint<std::string> allowed_poses(pose_sources);
  TCLAP::ValueArg<std::string> pose_source(
      "", "poses",
      "Robot poses from the ground truth (default), from the rawlog's pose observations "
      "(novelty-poses) or from its wheel odometry; the ground truth still gives the evaluation "
      "masks",
      false, "groundtruth", &allowed_poses, cmd);
  TCLAP::ValueArg<double> reduction("", "view-reduction",
                                    "Space reference views N times wider than configured: the "
                                    "thesis's R2 and R4 experiments (fig. 4.13) use 2 and 4",
                                    false, 1.0, "N", cmd);
  TCLAP::ValueArg<std::string> compare_views(
      "", "compare-views",
      "Also run maps with reference views N times sparser, side by side, e.g. 2,4 (fig. 4.13's "
      "R2 and R4); the report compares each finding's peak selectivity",
      false, "", "N,M", cmd);
  cmd.Parse(argc, argv);
  RunArgs a;
  a.rawlog = rawlog.getValue();
  a.truth = truth.getValue();
  a.out = out.getValue();
  a.config = config.getValue();
  a.map_in = map_in.getValue();
  a.objects_in = objects_in.getValue();
  a.objects_from = objects_from.getValue();
  if (a.objects_from < 1) throw std::invalid_argument("--objects-from must be >= 1");
  a.map_out = map_out.isSet() ? map_out.getValue() : a.out + "/map.appearance_map";
  a.compare_views = compare_views.getValue();
  if (max_frames.isSet()) a.max_frames = max_frames.getValue();
  a.panels_every = panels_every.getValue();
  a.pose_source = pose_source.getValue();
  a.reduction = reduction.getValue();
  if (!(a.reduction >= 1.0)) throw std::invalid_argument("--view-reduction must be >= 1");
  if (a.panels_every < 1) throw std::invalid_argument("--panels-every must be >= 1");
  if (a.max_frames && *a.max_frames < 1) throw std::invalid_argument("--frames must be >= 1");
  // Where the map goes is checked before the run, not after it.
  if (std::filesystem::is_directory(a.map_out))
    throw std::runtime_error("--map-out " + a.map_out + ": is a directory");
  // Outputs never replace inputs (--map-out may be --map-in: a map continued and saved back).
  for (const std::string& input : {a.rawlog, a.config}) {
    if (!input.empty() && core::SameFile(input, a.map_out))
      throw std::runtime_error("--map-out " + a.map_out + " is the input " + input);
  }
  if (std::filesystem::exists(a.out) && !std::filesystem::is_directory(a.out))
    throw std::runtime_error("--out " + a.out + ": is a file, not a folder");
  return a;
}

// The maps' .ini: --config (checked to be a text file), else kDefaultMaps.
std::unique_ptr<mrpt::config::CConfigFileBase> OpenMapsConfig(const std::string& path) {
  if (path.empty()) return std::make_unique<mrpt::config::CConfigFileMemory>(kDefaultMaps);
  return mrpt_plugins::OpenConfigFile(path);
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
};

// Plays the rawlog into the maps; per frame the selectivity of every changed region (metrics.csv,
// and the sparser maps' rows), every K-th panel, progress on stderr.
Played Play(const RunArgs& a, RunMaps& maps, const sim::GroundTruthReader& ground_truth,
            mrpt_plugins::RawlogMapPlayer& player) {
  mrpt_plugins::CAppearanceMap& map = maps.appearance();
  eval::SelectivityCsv csv(a.out + "/metrics.csv");
  std::optional<eval::ObjectStepsCsv> object_steps;
  if (maps.objects()) object_steps.emplace(a.out + "/objects.csv");
  int objects_used = 0;  // frames the object database took so far
  if (maps.objects()) maps.objects()->setPaused(a.objects_from > 1);
  Played run;
  int index = 0;
  const auto start = std::chrono::steady_clock::now();
  const int poses = int(ground_truth.CameraPoses().size());
  apps::Progress progress("novelty-run: playing",
                          a.max_frames ? std::min(*a.max_frames, poses) : poses);
  while ((!a.max_frames || run.frames < *a.max_frames) && player.Next(maps.multi, index)) {
    // The next frame is index + 1: the object database takes it from --objects-from on.
    if (maps.objects()) maps.objects()->setPaused(index + 1 < a.objects_from);
    const appearance::AppearanceProducts& p = map.lastProducts();
    const appearance::DifferencingProducts& d = maps.differencing().lastProducts();
    ++run.frames;
    if (object_steps && maps.objects()->framesUsed() != objects_used) {
      objects_used = maps.objects()->framesUsed();
      object_steps->Add(index, maps.objects()->lastStep(), maps.objects()->database().features());
    }
    for (const auto& [object, region] : ground_truth.ChangedRegions(index, 30)) {
      run.rows.push_back({index, object, eval::AttentionalSelectivity(p.surprise, region),
                          eval::AttentionalSelectivity(d.difference, region)});
      csv.Add(run.rows.back(), ground_truth.PhaseOf(index));
      for (std::size_t k = 0; k < maps.sparser_factors.size(); ++k) {
        maps.sparser_rows[k].push_back(
            {index, object,
             eval::AttentionalSelectivity(maps.appearance(k + 1).lastProducts().surprise, region),
             eval::AttentionalSelectivity(maps.differencing(k + 1).lastProducts().difference,
                                          region)});
      }
    }
    if (index % a.panels_every == 0) {
      const std::string stem = core::FrameStem(index);
      core::WriteRgbImage(a.out + "/panels/" + stem + ".png",
                          eval::NoveltyPanel(map.lastFrame().rgb, p, d, stem));
      run.panel_frames.push_back(index);
    }
    run.warp_sigma_sum += p.warp_sigma_px;
    if (!p.aligned_rotation.isZero()) {
      run.aligned_deg_sum += p.aligned_rotation.norm() * 180.0 / M_PI;
      ++run.aligned_frames;
    }
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    progress.Update(index);
  }
  progress.Finish();
  return run;
}

// Skipped frames in one line on stderr (one line per frame can be thousands) and as a note for
// the report; an early end of the rawlog too.
std::vector<std::string> SkipNotes(const mrpt_plugins::RawlogMapPlayer& player, int frames) {
  const auto& reasons = player.skip_reasons();
  std::vector<std::string> notes;
  if (!reasons.empty()) {
    notes.push_back(apps::SkippedFramesSummary(frames + int(reasons.size()), reasons));
    std::fprintf(stderr, "novelty-run: %s\n", notes.back().c_str());
  }
  if (!player.stopped_by().empty()) {
    notes.push_back("The rawlog ends early: " + player.stopped_by() + ". Results cover the " +
                    std::to_string(frames) + " frames read.");
    std::fprintf(stderr, "novelty-run: %s\n", notes.back().c_str());
  }
  return notes;
}

int Run(int argc, char** argv) {
  RunArgs a = ParseArgs(argc, argv);
  // Results go to OUT.partial, renamed at the end; the map too when it goes inside OUT.
  apps::OutputFolder folder("novelty-run", a.out,
                            {a.rawlog, a.truth, a.config, a.map_in, a.objects_in});
  const std::string out = a.out;
  const bool map_inside = a.map_out.rfind(out + "/", 0) == 0;
  a.out = folder.path();
  if (map_inside) a.map_out = folder.path() + a.map_out.substr(out.size());
  const std::unique_ptr<mrpt::config::CConfigFileBase> ini = OpenMapsConfig(a.config);
  RunMaps maps(*ini, a.config.empty() ? "default maps" : a.config, a.reduction,
               ParseFactors(a.compare_views));
  mrpt_plugins::CAppearanceMap& map = maps.appearance();
  if (!a.map_in.empty()) {
    map.LoadFromFile(a.map_in);
    std::fprintf(stderr,
                 "novelty-run: continuing %s with the options saved in it (the .ini's options "
                 "and --view-reduction apply to the other maps)\n",
                 a.map_in.c_str());
  }
  if (!a.objects_in.empty()) {
    if (!maps.objects())
      throw std::invalid_argument("--objects-in " + a.objects_in +
                                  ": --config declares no CObjectDatabaseMap to load it into");
    maps.objects()->LoadFromFile(a.objects_in);
    std::fprintf(stderr,
                 "novelty-run: object database from %s, with the options saved in it (the "
                 ".ini's CObjectDatabaseMap options do not apply)\n",
                 a.objects_in.c_str());
  }
  const sim::GroundTruthReader ground_truth(a.truth);
  std::filesystem::create_directories(a.out + "/panels");
  if (const auto parent = std::filesystem::path(a.map_out).parent_path(); !parent.empty())
    std::filesystem::create_directories(parent);
  mrpt_plugins::RawlogMapPlayer player(a.rawlog, mrpt_plugins::ParsePoseSource(a.pose_source),
                                       ground_truth.CameraPoses());
  const Played run = Play(a, maps, ground_truth, player);
  if (run.frames == 0) {  // nothing to report, and a saved map must not be replaced by an empty one
    const auto& reasons = player.skip_reasons();
    throw std::runtime_error(a.rawlog + ": no frame was inserted into the maps (" +
                             (reasons.empty() ? std::string("no camera observation")
                                              : apps::SkippedFramesSummary(0, reasons)) +
                             ")");
  }
  const std::vector<std::string> notes = SkipNotes(player, run.frames);
  std::printf("Findings of thesis 4.3 (surprise vs differencing, first run after each change):\n");
  WriteReport(a.out, run.rows, ground_truth.Phases(),
              ThesisFindings(ground_truth.Phases(), ground_truth.CameraPoses()), maps,
              run.panel_frames, run.frames, run.seconds, map.map().store().size(), notes);
  map.SaveToFile(a.map_out);
  map.SaveSceneFile(a.out + "/map.3Dscene");  // for SceneViewer3D
  if (const mrpt_plugins::CObjectDatabaseMap* objects = maps.objects())
    objects->SaveToFile(a.out + "/map.object_database");
  folder.Commit();
  a.out = out;
  if (map_inside) a.map_out = out + a.map_out.substr(folder.path().size());
  if (const mrpt_plugins::CObjectDatabaseMap* objects = maps.objects())
    std::printf("  objects: %s/objects.csv, %s/map.object_database\n  %s\n", a.out.c_str(),
                a.out.c_str(), objects->asString().c_str());
  std::printf(
      "%d frames (%d skipped) in %.1f s\n  metrics: %s/metrics.csv\n"
      "  map:     %s (%s)\n  report:  %s/report.html\n",
      run.frames, player.skipped(), run.seconds, a.out.c_str(), a.map_out.c_str(),
      map.asString().c_str(), a.out.c_str());
  if (run.warp_sigma_sum > 0.0)
    std::printf("  warp-error floor: s = %.2f px on average over the frames\n",
                run.warp_sigma_sum / run.frames);
  if (run.aligned_frames > 0)
    std::printf("  aligned to the prior: %d frames, by %.3f deg on average\n", run.aligned_frames,
                run.aligned_deg_sum / run.aligned_frames);
  return player.stopped_by().empty() ? apps::kExitOk : apps::kExitPartial;
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-run", [&] { return Run(argc, argv); });
}
