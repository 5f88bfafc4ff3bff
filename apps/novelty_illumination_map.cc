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
// the map atomically. Judging writes OUT/novelty/FRAME.png (Δ in false colour), OUT/frames.csv
// (per frame: coverage, regions, matched regions, mean and largest Δ; with --groundtruth the
// pixel AUC of Δ against the novelty mask), OUT/findings.csv and OUT/report.html with a panel
// (camera, invariant image, information i_Y, Δ) every --panels-every frames. Frames that cannot
// be used are skipped and counted.
#include <tclap/CmdLine.h>

#include <mrpt/maps/CMultiMetricMap.h>

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
#include "core/false_color.h"
#include "core/write_rgb_image.h"
#include "eval/html_report.h"
#include "eval/roc.h"
#include "eval/side_by_side.h"
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
  std::string path;
  int first = 1, last = 0;  // last 0: to the end
};

Pass ParsePass(const std::string& spec, const sim::GroundTruthReader* truth) {
  static const std::regex range(R"((.*):(\d+)-(\d+))"), named(R"((.*):([A-Za-z_][\w-]*))");
  std::smatch m;
  if (std::regex_match(spec, m, range))
    return {m[1].str(), std::stoi(m[2].str()), std::stoi(m[3].str())};
  if (std::regex_match(spec, m, named) && !fs::exists(spec)) {
    if (!truth)
      throw std::invalid_argument(spec +
                                  ": a phase name needs --groundtruth (novelty-sim's folder)");
    for (const auto& p : truth->Phases())
      if (p.name == m[2].str()) return {m[1].str(), p.first, p.last};
    throw std::invalid_argument(spec + ": no phase '" + m[2].str() + "' in " + truth->dir());
  }
  return {spec, 1, 0};
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

// Reports the frames a player skipped; returns how many.
int ReportSkips(const mrpt_plugins::RawlogMapPlayer& player, const std::string& what) {
  for (std::size_t i = 0; i < player.skip_reasons().size() && i < 3; ++i)
    std::fprintf(stderr, "[novelty-illumination-map] %s: skipped %s\n", what.c_str(),
                 player.skip_reasons()[i].c_str());
  if (!player.stopped_by().empty())
    std::fprintf(stderr, "[novelty-illumination-map] %s ends early: %s\n", what.c_str(),
                 player.stopped_by().c_str());
  return player.skipped();
}

int Learn(const std::vector<std::string>& lightings, const std::string& ini,
          const std::string& map_out, const std::string& poses,
          const sim::GroundTruthReader* truth) {
  Multimap m;
  Open(m, ini);
  const auto start = std::chrono::steady_clock::now();
  int skipped = 0;
  for (std::size_t k = 0; k < lightings.size(); ++k) {
    const Pass pass = ParsePass(lightings[k], truth);
    const auto player = MakePlayer(pass, poses, truth);
    m.map->beginLighting();
    int frames = 0;
    for (int frame = 0; player->Next(m.maps, frame);) {
      ++frames;
      std::fprintf(stderr, "\r[novelty-illumination-map] lighting %zu/%zu: frame %d   ", k + 1,
                   lightings.size(), frame);
    }
    std::fprintf(stderr, "\r[novelty-illumination-map] lighting %zu/%zu: %d frames from %s\n",
                 k + 1, lightings.size(), frames, lightings[k].c_str());
    skipped += ReportSkips(*player, lightings[k]);
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

int Judge(const std::string& map_in, const std::string& rawlog, const std::string& out,
          const std::string& poses, const sim::GroundTruthReader* truth, int panels_every) {
  Multimap m;
  Open(m, "");
  m.map->LoadFromFile(map_in);
  const Pass pass = ParsePass(rawlog, truth);
  const auto player = MakePlayer(pass, poses, truth);
  fs::create_directories(fs::path(out) / "novelty");
  fs::create_directories(fs::path(out) / "panels");
  std::ofstream frames_csv(fs::path(out) / "frames.csv");
  frames_csv << "frame,coverage,regions,matched,mean_delta,max_delta,auc\n";
  eval::HtmlReport report("novelty-illumination-map: " + rawlog + " against " + map_in);
  std::vector<double> scores;
  std::vector<bool> positive;
  int frames = 0;
  double seconds = 0.0;
  for (int frame = 0;;) {
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
    frames_csv << frame << ',' << r.coverage << ',' << r.novelty.region_count << ','
               << r.novelty.matched_count << ',' << mean_delta << ',' << max_delta << ','
               << (std::isnan(auc) ? std::string() : std::to_string(auc)) << '\n';
    if (covered) {
      // Δ on a fixed scale, so that frames compare: twice T_Y, where i_Y starts a region.
      const double scale = 2.0 * r.viewpoint.model.threshold;
      const cv::Mat delta = core::FalseColor(r.novelty.novelty, scale);
      core::WriteRgbImage((fs::path(out) / "novelty" / cv::format("%06d.png", frame)).string(),
                          delta);
      if (panels_every > 0 && (frames - 1) % panels_every == 0) {
        cv::Mat information = r.novelty.information_y.clone();
        information.setTo(0.0f, r.viewpoint.covered == 0);
        const std::string panel = cv::format("panels/%06d.png", frame);
        core::WriteRgbImage((fs::path(out) / panel).string(),
                            eval::SideBySide({m.map->lastFrame().rgb,
                                              illumination::LinearImage8(r.viewpoint.log_invariant,
                                                                         r.viewpoint.covered),
                                              core::FalseColor(information, scale), delta},
                                             4,
                                             {cv::format("frame %d", frame), "invariant image",
                                              "information i_Y", "novelty (6.3)"}));
        report.Image(panel, cv::format("frame %d: %.0f %% covered, %d regions", frame,
                                       100 * r.coverage, r.novelty.region_count));
      }
    }
    std::fprintf(stderr, "\r[novelty-illumination-map] frame %d: %.0f %% covered   ", frame,
                 100 * r.coverage);
  }
  std::fprintf(stderr, "\n");
  const int skipped = ReportSkips(*player, rawlog);
  if (frames == 0) throw std::invalid_argument(rawlog + ": no frame could be judged");
  std::ofstream findings(fs::path(out) / "findings.csv");
  findings << "finding,value\nframes judged," << frames << "\nframes skipped," << skipped
           << "\nms per frame," << 1000 * seconds / frames << "\n";
  std::string summary = cv::format("%d frames judged, %d skipped, %.1f ms a frame", frames, skipped,
                                   1000 * seconds / frames);
  const long n = long(std::count(positive.begin(), positive.end(), true));
  if (n > 0 && n < long(positive.size())) {
    const eval::Roc roc = eval::ComputeRoc(scores, positive);
    findings << "pixel AUC of novelty over all frames," << roc.auc << "\nTPR at FPR 1 %,"
             << roc.TprAtFpr(0.01) << "\n";
    summary +=
        cv::format("; pixel AUC %.3f, TPR at FPR 1 %% %.1f %%", roc.auc, 100 * roc.TprAtFpr(0.01));
  }
  report.Paragraph(summary);
  report.Save((fs::path(out) / "report.html").string());
  std::printf("%s → %s/report.html\n", summary.c_str(), out.c_str());
  return player->stopped_by().empty() ? 0 : 3;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    apps::CommandLine cmd(
        "Learn the illumination-invariant map (thesis ch. 6) from one rawlog pass per lighting, or "
        "judge a rawlog's frames with a learnt map",
        "0.1");
    TCLAP::MultiArg<std::string> lighting(
        "", "lighting", "Learning: one lighting's pass, RAWLOG[:FIRST-LAST|:PHASE]; repeat", false,
        "RAWLOG", cmd);
    TCLAP::ValueArg<std::string> map_out("", "map-out", "Learning: where to save the map", false,
                                         "", "FILE", cmd);
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
        "Camera poses: the rawlog's pose observations (novelty-poses), wheel odometry or the "
        "ground truth's",
        false, "rawlog", &pose_names, cmd);
    TCLAP::ValueArg<std::string> truth_dir(
        "", "groundtruth", "novelty-sim's ground-truth folder (poses, phases, novelty masks)",
        false, "", "DIR", cmd);
    TCLAP::ValueArg<int> panels_every("", "panels-every", "Judging: a panel every K frames", false,
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
    if (panels_every.getValue() < 0) throw std::invalid_argument("--panels-every must be >= 0");
    std::optional<sim::GroundTruthReader> truth;
    if (truth_dir.isSet()) truth.emplace(truth_dir.getValue());
    const sim::GroundTruthReader* t = truth ? &*truth : nullptr;
    return learning
               ? Learn(lighting.getValue(), ini.getValue(), map_out.getValue(), poses.getValue(), t)
               : Judge(map_in.getValue(), rawlog.getValue(), out.getValue(), poses.getValue(), t,
                       panels_every.getValue());
  } catch (const TCLAP::ArgException& e) {
    std::fprintf(stderr, "novelty-illumination-map: %s (%s)\n", e.error().c_str(),
                 e.argId().c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "novelty-illumination-map: %s\n", e.what());
  }
  return 1;
}
