// novelty-illumination-map: the illumination-invariant map (thesis ch. 6) from rawlogs, as a robot
// would use it — learn it from one pass per lighting and save it, then judge new frames with it.
//
//   novelty-illumination-map --lighting L1 --lighting L2 [...] --map-out MAP
//       [--ini share/illumination_invariant.ini] [--poses rawlog|odometry|groundtruth]
//       [--groundtruth DIR]
//   novelty-illumination-map --map-in MAP --rawlog R --out OUT [--poses ...] [--groundtruth DIR]
//       [--panels-every 10]
//
// A lighting, and the rawlog to judge, is a rawlog path, optionally with ":FIRST-LAST" (its
// frames FIRST…LAST, 1-based over its camera frames) or ":PHASE" (a phase of --groundtruth,
// novelty-sim's folder), so that one rawlog holding several passes serves too. Frames are played
// into a CMultiMetricMap holding one CIlluminationInvariantMap (the .ini's; default
// share/illumination_invariant.ini), with poses from the rawlog's pose observations
// (novelty-poses; the default), the wheel odometry or the ground truth's camera poses. Learning
// calls beginLighting() before each lighting and finishAcquisition() after the last, then saves
// the map atomically (--map-out replaces an earlier map, nothing else). Judging writes
// OUT/novelty/FRAME.png (Δ in false colour), OUT/frames.csv
// (per frame: coverage, regions, matched regions, mean and largest Δ; with --groundtruth the
// pixel AUC of Δ against the novelty mask), OUT/findings.csv (finding,value,target,holds) and
// OUT/report.html: plots of Δ, coverage and AUC per frame, the pixel ROC (with --groundtruth), and
// a panel (camera, invariant image, information i_Y, Δ) every --panels-every frames; all of it into
// OUT.partial, renamed to OUT at the end (OUT may be an earlier output, nothing else), so a failed
// run leaves the earlier output whole. Frames that cannot be used are skipped and counted; a
// rawlog that ends early, or before the frames asked, gives results and exit 3.
#include <tclap/CmdLine.h>

#include <mrpt/maps/CMultiMetricMap.h>

#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "apps/command_line.h"
#include "apps/shell/output_folder.h"
#include "apps/shell/program.h"
#include "apps/shell/progress.h"
#include "core/false_color.h"
#include "core/write_rgb_image.h"
#include "eval/findings_table.h"
#include "eval/html_report.h"
#include "eval/roc.h"
#include "eval/roc_plot.h"
#include "eval/side_by_side.h"
#include "eval/skipped_frames.h"
#include "maps/illumination/invariant_image.h"
#include "mrpt_plugins/c_illumination_invariant_map.h"
#include "mrpt_plugins/multi_map_config.h"
#include "mrpt_plugins/rawlog_map_player.h"
#include "sim/output/ground_truth_reader.h"

using namespace novelty;
namespace fs = std::filesystem;

namespace {

// A rawlog and the frames of it to play.
struct Pass {
  std::string spec;  // as given, for messages
  std::string path;
  int first = 1, last = 0;  // last 0: to the end
};

// RAWLOG, RAWLOG:FIRST-LAST or RAWLOG:PHASE; the rawlog must be a file.
Pass ParsePass(const std::string& spec, const sim::GroundTruthReader* truth) {
  static const std::regex range(R"((.*):(\d+)-(\d+))"), named(R"((.*):([A-Za-z_][\w-]*))");
  std::smatch m;
  Pass pass{spec, spec, 1, 0};
  if (fs::is_regular_file(spec)) {
    pass.path = spec;
  } else if (std::regex_match(spec, m, range)) {
    pass.path = m[1].str();
    try {
      pass.first = std::stoi(m[2].str()), pass.last = std::stoi(m[3].str());
    } catch (const std::out_of_range&) {
      pass.first = pass.last = 0;
    }
    if (pass.first < 1 || pass.last < pass.first)
      throw std::invalid_argument(spec + ": frames " + m[2].str() + "-" + m[3].str() +
                                  " are no range (1-based, first <= last)");
  } else if (std::regex_match(spec, m, named)) {
    pass.path = m[1].str();
    if (!truth)
      throw std::invalid_argument(spec +
                                  ": a phase name needs --groundtruth (novelty-sim's folder)");
    const auto& phases = truth->Phases();
    const auto phase = std::find_if(phases.begin(), phases.end(),
                                    [&](const auto& p) { return p.name == m[2].str(); });
    if (phase == phases.end())
      throw std::invalid_argument(spec + ": no phase '" + m[2].str() + "' in " + truth->dir());
    pass.first = phase->first, pass.last = phase->last;
  }
  if (!fs::is_regular_file(pass.path))
    throw std::invalid_argument(spec + (fs::exists(pass.path)
                                            ? ": " + pass.path + " is not a file"
                                            : ": no such rawlog (RAWLOG, RAWLOG:FIRST-LAST or "
                                              "RAWLOG:PHASE)"));
  return pass;
}

// Says what a pass that gave no frame lacked.
std::string NoFrameHint(const std::string& poses) {
  return poses == "rawlog" ? " (--poses rawlog needs the pose observations novelty-poses writes; "
                             "a simulator's rawlog: --poses groundtruth --groundtruth DIR)"
                           : "";
}

struct Multimap {
  mrpt::maps::CMultiMetricMap maps;
  std::shared_ptr<mrpt_plugins::CIlluminationInvariantMap> map;
};

// The multimap of `ini`, or one default CIlluminationInvariantMap without.
void Open(Multimap& m, const std::string& ini) {
  if (ini.empty()) {
    m.map = std::make_shared<mrpt_plugins::CIlluminationInvariantMap>();
    m.maps.maps.push_back(m.map);
    return;
  }
  m.maps.setListOfMaps(mrpt_plugins::LoadMultiMapConfig(ini));
  m.map = m.maps.mapByClass<mrpt_plugins::CIlluminationInvariantMap>();
  if (!m.map) throw std::invalid_argument(ini + " declares no CIlluminationInvariantMap");
  if (m.maps.mapByClass<mrpt_plugins::CIlluminationInvariantMap>(1))
    throw std::invalid_argument(ini +
                                " declares more than one CIlluminationInvariantMap; "
                                "--map-out saves one");
}

std::unique_ptr<mrpt_plugins::RawlogMapPlayer> MakePlayer(const Pass& pass,
                                                          const std::string& poses,
                                                          const sim::GroundTruthReader* truth) {
  const mrpt_plugins::PoseSource source = mrpt_plugins::ParsePoseSource(poses);
  if (source == mrpt_plugins::PoseSource::kGroundTruth && !truth)
    throw std::invalid_argument("--poses groundtruth needs --groundtruth");
  auto player = std::make_unique<mrpt_plugins::RawlogMapPlayer>(
      pass.path, source,
      source == mrpt_plugins::PoseSource::kGroundTruth ? truth->CameraPoses()
                                                       : std::map<int, Eigen::Isometry3d>{});
  if (pass.last > 0) player->SetFrameRange(pass.first, pass.last);
  return player;
}

// Reports the frames a player skipped (one line) and an early end; returns how many it skipped.
int ReportSkips(const mrpt_plugins::RawlogMapPlayer& player, const std::string& what, int frames) {
  if (player.skipped())
    std::fprintf(
        stderr, "[novelty-illumination-map] %s: %s\n", what.c_str(),
        eval::SkippedFramesSummary(frames + player.skipped(), player.skip_reasons()).c_str());
  if (!player.stopped_by().empty())
    std::fprintf(stderr, "[novelty-illumination-map] %s ends early: %s\n", what.c_str(),
                 player.stopped_by().c_str());
  return player.skipped();
}

// Plays a pass into the maps; throws when no frame of it could be used, naming the pass.
int PlayPass(const Pass& pass, const std::string& poses, const sim::GroundTruthReader* truth,
             Multimap& m, const std::string& what, int& skipped) {
  const auto player = MakePlayer(pass, poses, truth);
  int frames = 0, last = 0;
  {
    apps::Progress progress("[novelty-illumination-map] " + what,
                            pass.last > 0 ? pass.last - pass.first + 1 : 0);
    for (int frame = 0; player->Next(m.maps, frame); last = frame) progress.Update(++frames);
  }
  std::fprintf(stderr, "[novelty-illumination-map] %s: %d frames from %s\n", what.c_str(), frames,
               pass.spec.c_str());
  if (frames == 0)  // one line: the first reason says it
    throw std::invalid_argument(
        what + " (" + pass.spec + "): no frame could be used" +
        (player->skipped() ? " (" + player->skip_reasons().front() + ")" : "") +
        NoFrameHint(poses));
  skipped += ReportSkips(*player, pass.spec, frames);
  if (pass.last > 0 && last < pass.last)
    std::fprintf(stderr,
                 "[novelty-illumination-map] %s: frames %d-%d asked, the last one used is %d\n",
                 pass.spec.c_str(), pass.first, pass.last, last);
  return frames;
}

// --map-out may replace an earlier map, never anything else (a rawlog given by mistake).
void CheckMapOut(const std::string& map_out) {
  const fs::path parent = fs::path(map_out).parent_path();
  if (!parent.empty() && !fs::is_directory(parent))
    throw std::invalid_argument("--map-out " + map_out + ": no folder " + parent.string());
  if (!fs::exists(map_out)) return;
  try {
    mrpt_plugins::CIlluminationInvariantMap probe;
    probe.LoadFromFile(map_out);
  } catch (const std::exception&) {
    throw std::invalid_argument("--map-out " + map_out +
                                " exists and is not an illumination-invariant map: not replacing "
                                "it");
  }
}

int Learn(const std::vector<std::string>& lightings, const std::string& ini,
          const std::string& map_out, const std::string& poses,
          const sim::GroundTruthReader* truth) {
  // Everything a typo can break is checked before the first frame is read.
  std::vector<Pass> passes;
  for (const std::string& spec : lightings) passes.push_back(ParsePass(spec, truth));
  CheckMapOut(map_out);
  Multimap m;
  Open(m, ini);
  const auto start = std::chrono::steady_clock::now();
  int skipped = 0;
  for (std::size_t k = 0; k < passes.size(); ++k) {
    m.map->beginLighting();
    PlayPass(passes[k], poses, truth, m,
             "lighting " + std::to_string(k + 1) + "/" + std::to_string(passes.size()), skipped);
  }
  std::fprintf(stderr, "[novelty-illumination-map] invariant images at the viewpoints ...\n");
  m.map->finishAcquisition();
  m.map->SaveToFile(map_out);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%s\n%d frames skipped; learnt in %.1f s → %s\n", m.map->asString().c_str(), skipped,
              seconds, map_out.c_str());
  return 0;
}

// Pixel AUC of Δ against the truth's novelty mask over the covered pixels (NaN when the frame
// shows no novelty or no background).
double FrameAuc(const illumination::IlluminationMapResult& r, const cv::Mat& truth) {
  std::vector<double> scores;
  std::vector<bool> positive;
  for (int y = 0; y < truth.rows; ++y)
    for (int x = 0; x < truth.cols; ++x)
      if (r.viewpoint.covered.at<uchar>(y, x)) {
        scores.push_back(r.novelty.novelty.at<float>(y, x));
        positive.push_back(truth.at<uchar>(y, x) != 0);
      }
  const long n = long(std::count(positive.begin(), positive.end(), true));
  if (n == 0 || n == long(positive.size())) return NAN;
  return eval::ComputeRoc(scores, positive).auc;
}

int Judge(const std::string& map_in, const std::string& rawlog, const std::string& out_dir,
          const std::string& poses, const sim::GroundTruthReader* truth, int panels_every) {
  const Pass pass = ParsePass(rawlog, truth);
  // Written aside and put in place at the end: a failed run leaves an earlier output whole.
  apps::OutputFolder folder("novelty-illumination-map", out_dir,
                            {map_in, pass.path, truth ? truth->dir() : ""});
  const fs::path out = folder.path();
  Multimap m;
  Open(m, "");
  m.map->LoadFromFile(map_in);
  const auto player = MakePlayer(pass, poses, truth);
  fs::create_directories(out / "novelty");
  fs::create_directories(out / "panels");
  std::ofstream frames_csv(out / "frames.csv");
  frames_csv << "frame,coverage,regions,matched,mean_delta,max_delta,auc\n";
  eval::HtmlReport report("novelty-illumination-map: " + rawlog + " against " + map_in);
  std::vector<double> scores;
  std::vector<bool> positive;
  // Per frame for the report's plots: coverage, mean and largest Δ, pixel AUC (NaN: none).
  eval::PlotSeries coverage_series{"covered share", "#0072b2", {}, 1.0},
      auc_series{"pixel AUC", "#d55e00", {}, 1.0}, mean_series{"mean Δ", "#009e73", {}, 1.0},
      max_series{"largest Δ", "#cc79a7", {}, 1.0};
  std::vector<std::pair<std::string, std::string>> panels;  // (path, caption), after the plots
  int frames = 0, last = 0;
  double seconds = 0.0;
  apps::Progress progress("[novelty-illumination-map] judging",
                          pass.last > 0 ? pass.last - pass.first + 1 : 0);
  for (int frame = 0;; last = frame) {
    const auto t0 = std::chrono::steady_clock::now();
    if (!player->Next(m.maps, frame)) break;
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ++frames;
    const illumination::IlluminationMapResult& r = m.map->lastResult();
    const bool covered = r.coverage > 0.0;
    double max_delta = 0.0;
    if (covered) cv::minMaxLoc(r.novelty.novelty, nullptr, &max_delta);
    const double mean_delta = covered ? cv::mean(r.novelty.novelty, r.viewpoint.covered)[0] : 0.0;
    double auc = NAN;
    if (truth && covered) {
      const cv::Mat mask = truth->Novelty(frame);
      if (mask.size() == r.novelty.novelty.size()) {
        auc = FrameAuc(r, mask);
        for (int y = 0; y < mask.rows; ++y)
          for (int x = 0; x < mask.cols; ++x)
            if (r.viewpoint.covered.at<uchar>(y, x)) {
              scores.push_back(r.novelty.novelty.at<float>(y, x));
              positive.push_back(mask.at<uchar>(y, x) != 0);
            }
      }
    }
    coverage_series.points.emplace_back(frame, r.coverage);
    auc_series.points.emplace_back(frame, auc);
    mean_series.points.emplace_back(frame, covered ? mean_delta : NAN);
    max_series.points.emplace_back(frame, covered ? max_delta : NAN);
    frames_csv << frame << ',' << r.coverage << ',' << r.novelty.region_count << ','
               << r.novelty.matched_count << ',' << mean_delta << ',' << max_delta << ','
               << (std::isnan(auc) ? std::string() : std::to_string(auc)) << '\n';
    if (covered) {
      // Δ on a fixed scale, so that frames compare: twice T_Y, where i_Y starts a region.
      const double scale = 2.0 * r.viewpoint.model.threshold;
      const cv::Mat delta = core::FalseColor(r.novelty.novelty, scale);
      core::WriteRgbImage((out / "novelty" / cv::format("%06d.png", frame)).string(), delta);
      if (panels_every > 0 && (frames - 1) % panels_every == 0) {
        cv::Mat information = r.novelty.information_y.clone();
        information.setTo(0.0f, r.viewpoint.covered == 0);
        const std::string panel = cv::format("panels/%06d.png", frame);
        core::WriteRgbImage((out / panel).string(),
                            eval::SideBySide({m.map->lastFrame().rgb,
                                              illumination::LinearImage8(r.viewpoint.log_invariant,
                                                                         r.viewpoint.covered),
                                              core::FalseColor(information, scale), delta},
                                             4,
                                             {cv::format("frame %d", frame), "invariant image",
                                              "information i_Y", "novelty (6.3)"}));
        panels.emplace_back(panel, cv::format("frame %d: %.0f %% covered, %d regions", frame,
                                              100 * r.coverage, r.novelty.region_count));
      }
    }
    progress.Update(frames);
  }
  progress.Finish();
  if (frames == 0) {
    throw std::invalid_argument(rawlog + ": no frame could be judged" +
                                (player->skipped() ? " (" + player->skip_reasons().front() + ")"
                                 : pass.last > 0
                                     ? " (no camera frame in " + std::to_string(pass.first) + "-" +
                                           std::to_string(pass.last) + ")"
                                     : " (no camera frame in it)") +
                                NoFrameHint(poses));
  }
  const int skipped = ReportSkips(*player, rawlog, frames);
  const bool short_range = pass.last > 0 && last < pass.last;
  if (short_range)
    std::fprintf(stderr,
                 "[novelty-illumination-map] %s: frames %d-%d asked, the last one judged is %d\n",
                 pass.spec.c_str(), pass.first, pass.last, last);
  eval::FindingsTable findings;
  findings.Add("frames judged", std::to_string(frames));
  findings.Add("frames skipped", std::to_string(skipped));
  findings.Add("ms per frame", eval::NumberText(1000 * seconds / frames));
  std::string summary = cv::format("%d frames judged, %d skipped, %.1f ms a frame", frames, skipped,
                                   1000 * seconds / frames);
  const long n = long(std::count(positive.begin(), positive.end(), true));
  std::optional<eval::Roc> roc;
  if (n > 0 && n < long(positive.size())) {
    roc = eval::ComputeRoc(scores, positive);
    findings.Add("pixel AUC of novelty over all frames", eval::NumberText(roc->auc), "(reported)");
    findings.Add("TPR at FPR 1 %", eval::NumberText(roc->TprAtFpr(0.01)), "(reported)");
    summary += cv::format("; pixel AUC %.3f, TPR at FPR 1 %% %.1f %%", roc->auc,
                          100 * roc->TprAtFpr(0.01));
  }
  report.Paragraph(summary);
  report.Paragraph(
      "frames.csv: per frame the share of pixels the map covers, the regions of i_Y > T_Y and how "
      "many a stored highlight or shadow shape explains, the mean and largest novelty Δ (nats, "
      "eq. 6.24) and, with --groundtruth, the pixel AUC of Δ against the novelty mask. Pictures: "
      "Δ and i_Y in false colour from 0 to 2·T_Y.");
  report.Heading("Per frame");
  report.Raw(eval::SvgLinePlot("Novelty Δ over the covered pixels", "frame", "Δ (nats)",
                               {mean_series, max_series}));
  std::vector<eval::PlotSeries> shares = {coverage_series};
  if (roc) shares.push_back(auc_series);
  report.Raw(
      eval::SvgLinePlot(roc ? "Coverage and pixel AUC" : "Coverage", "frame", "share", shares));
  if (roc) {
    report.Heading("ROC of Δ over the covered pixels of all frames");
    report.Raw(eval::SvgLinePlot("ROC", "FPR (%)", "TPR (%)",
                                 {eval::RocPlotSeries(*roc, "novelty Δ", "#0072b2")}));
    report.Raw(eval::SvgLinePlot("ROC at FPR up to 5 %", "FPR (%)", "TPR (%)",
                                 {eval::RocPlotSeries(*roc, "novelty Δ", "#0072b2", {0.05})}));
  }
  if (!panels.empty()) report.Heading("Panels");
  for (const auto& [path, caption] : panels) report.Image(path, caption);
  findings.WriteCsv((out / "findings.csv").string());
  report.Save((out / "report.html").string());
  frames_csv.close();
  folder.Commit();
  std::printf("%s → %s/report.html\n", summary.c_str(), out_dir.c_str());
  return player->stopped_by().empty() && !short_range ? apps::kExitOk : apps::kExitPartial;
}

int Run(int argc, char** argv) {
  apps::CommandLine cmd(
      "Learn the illumination-invariant map (thesis ch. 6) from one rawlog pass per lighting, or "
      "judge a rawlog's frames with a learnt map",
      "0.1");
  TCLAP::MultiArg<std::string> lighting(
      "", "lighting",
      "Learning: one lighting's pass, RAWLOG[:FIRST-LAST|:PHASE] (camera frames, 1-based, "
      "inclusive; PHASE of --groundtruth); repeat, at least twice",
      false, "RAWLOG", cmd);
  TCLAP::ValueArg<std::string> map_out("", "map-out", "Learning: where to save the map", false, "",
                                       "FILE", cmd);
  TCLAP::ValueArg<std::string> ini(
      "", "ini",
      "Learning: CMultiMetricMap .ini declaring the CIlluminationInvariantMap (default: its "
      "defaults, share/illumination_invariant.ini)",
      false, "", "FILE", cmd);
  TCLAP::ValueArg<std::string> map_in("", "map-in", "Judging: a learnt map", false, "", "FILE",
                                      cmd);
  TCLAP::ValueArg<std::string> rawlog("", "rawlog", "Judging: RAWLOG[:FIRST-LAST|:PHASE]", false,
                                      "", "RAWLOG", cmd);
  TCLAP::ValueArg<std::string> out("", "out", "Judging: output folder", false, "", "DIR", cmd);
  std::vector<std::string> pose_sources = {"rawlog", "odometry", "groundtruth"};
  TCLAP::ValuesConstraint<std::string> pose_names(pose_sources);
  TCLAP::ValueArg<std::string> poses(
      "", "poses",
      "Camera poses: the rawlog's pose observations (novelty-poses; default), wheel odometry or "
      "the ground truth's (needs --groundtruth)",
      false, "rawlog", &pose_names, cmd);
  TCLAP::ValueArg<std::string> truth_dir(
      "", "groundtruth", "novelty-sim's ground-truth folder (poses, phases, novelty masks)", false,
      "", "DIR", cmd);
  TCLAP::ValueArg<int> panels_every("", "panels-every",
                                    "Judging: a panel every K frames (default 10; 0: none)", false,
                                    10, "K", cmd);
  cmd.Parse(argc, argv);
  const bool learning = lighting.isSet(), judging = map_in.isSet();
  if (learning == judging)
    throw std::invalid_argument("give either --lighting (learning) or --map-in (judging)");
  if (learning && (lighting.getValue().size() < 2 || map_out.getValue().empty()))
    throw std::invalid_argument(
        "learning needs at least two --lighting passes (the median of one lighting is not "
        "invariant) and --map-out");
  if (judging && (rawlog.getValue().empty() || out.getValue().empty()))
    throw std::invalid_argument("judging needs --rawlog and --out");
  if (judging && (ini.isSet() || map_out.isSet()))
    throw std::invalid_argument(
        "--ini and --map-out are for learning; a judged map keeps the options it was learnt "
        "with");
  if (learning && (rawlog.isSet() || out.isSet()))
    throw std::invalid_argument("--rawlog and --out are for judging (with --map-in)");
  if (panels_every.getValue() < 0) throw std::invalid_argument("--panels-every must be >= 0");
  std::optional<sim::GroundTruthReader> truth;
  if (truth_dir.isSet()) truth.emplace(truth_dir.getValue());
  const sim::GroundTruthReader* t = truth ? &*truth : nullptr;
  return learning
             ? Learn(lighting.getValue(), ini.getValue(), map_out.getValue(), poses.getValue(), t)
             : Judge(map_in.getValue(), rawlog.getValue(), out.getValue(), poses.getValue(), t,
                     panels_every.getValue());
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-illumination-map", [&] { return Run(argc, argv); });
}
