// novelty-illumination-map: the illumination-invariant map (thesis ch. 6) as a robot would use
// it — learn it from one pass per lighting and save it, then judge new frames with it
// (experiments/illumination_map_run.h).
//
//   novelty-illumination-map --lighting L1 --lighting L2 [...] --map-out MAP [--ini INI]
//       [--poses rawlog|odometry|groundtruth] [--groundtruth DIR]
//   novelty-illumination-map --lighting PHOTOS_DIR --map-out MAP [--include GLOB] [--exclude GLOB]
//   novelty-illumination-map --map-in MAP --rawlog R|DIR --out OUT [--panels-every 10]
//
// A lighting, and what to judge, is a rawlog, RAWLOG:FIRST-LAST (camera frames, 1-based),
// RAWLOG:PHASE (of --groundtruth, novelty-sim's folder), or a folder of one fixed camera's images
// (each a lighting when learning, a frame when judging; mask.png limits the pixels). Poses come
// from the rawlog's pose observations (novelty-poses; the default), the wheel odometry or the
// ground truth. The map learns a decision threshold from its lightings (false_alarm_rate) and is
// saved atomically. Judging writes OUT/novelty/FRAME.png, frames.csv (coverage, regions, Δ, the
// share above the threshold, the AUC with --groundtruth), findings.csv and report.html (plots,
// the ROC with ground truth, panels) into OUT.partial, renamed at the end. Frames that cannot be
// used are skipped and counted; a rawlog that ends early gives results and exit 3.
#include <tclap/CmdLine.h>

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "apps/command_line.h"
#include "apps/shell/output_folder.h"
#include "apps/shell/program.h"
#include "apps/shell/progress.h"
#include "experiments/illumination_map_run.h"
#include "mrpt_plugins/map_file.h"

using namespace novelty;

namespace {

int Learn(const std::vector<std::string>& lightings, const std::string& ini,
          const std::string& map_out, const experiments::IlluminationMapRunOptions& o,
          std::optional<apps::Progress>& progress) {
  const experiments::LearnIlluminationMapResult r =
      experiments::LearnIlluminationMap(lightings, ini, map_out, o);
  if (progress) progress->Finish();
  std::printf("%s\n%d frames, %d skipped; learnt in %.1f s → %s\n", r.map_summary.c_str(), r.frames,
              r.skipped, r.seconds, map_out.c_str());
  return apps::kExitOk;
}

int Judge(const std::string& map_in, const std::string& rawlog, const std::string& out_dir,
          int panels_every, const experiments::IlluminationMapRunOptions& o,
          std::optional<apps::Progress>& progress) {
  const experiments::RawlogPass pass = experiments::ParseRawlogPass(rawlog, o.truth);
  // Written aside and put in place at the end: a failed run leaves an earlier output whole.
  apps::OutputFolder folder("novelty-illumination-map", out_dir,
                            {map_in, pass.path, o.truth ? o.truth->dir() : ""});
  const experiments::JudgeIlluminationMapResult r =
      experiments::JudgeIlluminationMap(map_in, rawlog, folder.path(), panels_every, o);
  if (progress) progress->Finish();
  folder.Commit();
  std::printf("%s → %s/report.html\n", r.summary.c_str(), out_dir.c_str());
  return r.ended_early ? apps::kExitPartial : apps::kExitOk;
}

int Run(int argc, char** argv) {
  apps::CommandLine cmd(
      "Learn the illumination-invariant map (thesis ch. 6) from one rawlog pass per lighting or a "
      "folder of photos, or "
      "judge a rawlog's frames or a folder's images with a learnt map",
      "0.1");
  TCLAP::MultiArg<std::string> lighting(
      "", "lighting",
      "Learning: one lighting's pass, RAWLOG[:FIRST-LAST|:PHASE] (camera frames, 1-based, "
      "inclusive; PHASE of --groundtruth), repeated; or a folder of photos, each a lighting",
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
  TCLAP::ValueArg<std::string> rawlog("", "rawlog", "Judging: RAWLOG[:FIRST-LAST|:PHASE] or DIR",
                                      false, "", "RAWLOG", cmd);
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
  TCLAP::MultiArg<std::string> include("", "include",
                                       "A folder's images: only files matching GLOB (repeatable)",
                                       false, "GLOB", cmd);
  TCLAP::MultiArg<std::string> exclude(
      "", "exclude", "A folder's images: not files matching GLOB (repeatable)", false, "GLOB", cmd);
  TCLAP::ValueArg<int> panels_every("", "panels-every",
                                    "Judging: a panel every K frames (default 10; 0: none)", false,
                                    10, "K", cmd);
  cmd.Parse(argc, argv);
  const bool learning = lighting.isSet(), judging = map_in.isSet();
  if (learning == judging)
    throw apps::UsageError("give either --lighting (learning) or --map-in (judging)");
  if (learning && map_out.getValue().empty())
    throw apps::UsageError("learning needs --map-out");
  if (judging && (rawlog.getValue().empty() || out.getValue().empty()))
    throw apps::UsageError("judging needs --rawlog and --out");
  if (judging && (ini.isSet() || map_out.isSet()))
    throw apps::UsageError(
        "--ini and --map-out are for learning; a judged map keeps the options it was learnt "
        "with");
  if (learning && (rawlog.isSet() || out.isSet()))
    throw apps::UsageError("--rawlog and --out are for judging (with --map-in)");
  std::optional<sim::GroundTruthReader> truth;
  if (truth_dir.isSet()) truth.emplace(truth_dir.getValue());
  experiments::IlluminationMapRunOptions o;
  o.poses = poses.getValue();
  o.truth = truth ? &*truth : nullptr;
  o.fixed_camera.pick = {include.getValue(), exclude.getValue()};
  o.status = [](const std::string& line) {
    std::fprintf(stderr, "[novelty-illumination-map] %s\n", line.c_str());
  };
  std::optional<apps::Progress> progress;
  std::string stage;
  o.progress = [&](const std::string& what, int frames, int total) {
    if (what != stage) progress.emplace("[novelty-illumination-map] " + what, total), stage = what;
    progress->Update(frames);
  };
  if (learning) {
    std::vector<std::string> inputs = {ini.getValue()};
    for (const std::string& spec : lighting.getValue())
      inputs.push_back(experiments::ParseRawlogPass(spec, o.truth).path);
    apps::CheckOutputFile("--map-out", map_out.getValue(), inputs, [](const std::string& p) {
      return mrpt_plugins::IsMapFileOf(p, "CIlluminationInvariantMap");
    });
    return Learn(lighting.getValue(), ini.getValue(), map_out.getValue(), o, progress);
  }
  return Judge(map_in.getValue(), rawlog.getValue(), out.getValue(), panels_every.getValue(), o,
               progress);
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-illumination-map", [&] { return Run(argc, argv); });
}
