// novelty-run: the surprise pipeline (thesis ch. 4) over an RGB-D rawlog, the experiment of
// thesis 4.3 (experiments/surprise_experiment.h says what it runs and writes).
//
//   novelty-run --rawlog DIR/<name>.rawlog [--groundtruth DIR/groundtruth] --out OUT
//               [--config share/novelty_run.ini] [--frames N] [--panels-every K]
//               [--poses groundtruth|rawlog|odometry] [--compare-views 2,4]
//               [--map-in M] [--map-out M] [--objects-in D] [--objects-from N] [--view-reduction N]
//               [--learn-until N] [--novelty-z Z]
//
// OUT: panels/, frames.csv, metrics.csv, findings.csv, report.html, map.3Dscene, the appearance
// map (OUT/map.appearance_map unless --map-out), and with a CObjectDatabaseMap in the .ini
// objects.csv and map.object_database.
//
// Exit status: 0 done; 1 an error (one line on stderr; nothing overwritten, no map saved when no
// frame was inserted); 2 bad command line; 3 the rawlog ends early (cut short or corrupt): the
// results and the map cover the frames read, and stderr names where it ended.
#include <tclap/CmdLine.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

#include "apps/command_line.h"
#include "apps/shell/output_folder.h"
#include "apps/shell/program.h"
#include "apps/shell/progress.h"
#include "core/same_file.h"
#include "experiments/surprise_experiment.h"
#include "mrpt_plugins/map_file.h"

namespace {

using namespace novelty;

// What the command line asks for.
struct RunArgs {
  std::string rawlog, truth, out, config, map_in, map_out, compare_views, objects_in;
  std::optional<int> max_frames;
  int panels_every = 10;
  int objects_from = 1, learn_until = 0;
  std::string pose_source = "groundtruth";
  double reduction = 1.0, z = 0.0;
};

// Parses and checks the command line; throws TCLAP::ArgException or std::invalid_argument.
RunArgs ParseArgs(int argc, char** argv) {
  novelty::apps::CommandLine cmd(
      "Bayesian surprise with the probabilistic appearance map over an RGB-D rawlog, against "
      "image differencing if the maps hold it, through MRPT's CMultiMetricMap.",
      "0.1");
  TCLAP::ValueArg<std::string> rawlog("", "rawlog", "RGB-D rawlog", true, "", "R.rawlog", cmd);
  TCLAP::ValueArg<std::string> truth("", "groundtruth",
                                     "Ground-truth folder (poses, masks): scores the run; without "
                                     "it, take --poses rawlog or odometry",
                                     false, "", "DIR", cmd);
  TCLAP::ValueArg<std::string> out("", "out", "Output folder", true, "", "OUT", cmd);
  TCLAP::ValueArg<std::string> config(
      "", "config",
      "The maps as a CMultiMetricMap .ini (section [map]: CAppearanceMap_count = 1, "
      "CDifferencingMap_count 0 or 1, which --groundtruth scores against; options in "
      "[map_CAppearanceMap_00_options] ...), e.g. "
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
      "map learns the room alone (the thesis's I1: 361 for share/scenarios/object_learning.scn)",
      false, 1, "N", cmd);
  std::vector<std::string> pose_sources = {"groundtruth", "rawlog", "odometry"};
  TCLAP::ValuesConstraint<std::string> allowed_poses(pose_sources);
  TCLAP::ValueArg<std::string> pose_source(
      "", "poses",
      "Robot poses from the ground truth (the default with --groundtruth), from the rawlog's pose "
      "observations (the default without; novelty-import, novelty-poses) or from its wheel "
      "odometry; the ground truth still gives the evaluation masks",
      false, "groundtruth", &allowed_poses, cmd);
  const double default_z = eval::NoveltyVerdictOptions().z;
  char z_text[32];
  std::snprintf(z_text, sizeof z_text, "%g", default_z);
  TCLAP::ValueArg<double> z("", "novelty-z",
                            "For the report's verdict, a frame shows something new when its "
                            "most surprising 50 pixels stand Z robust deviations above the run's "
                            "median frame (default " +
                                std::string(z_text) + ")",
                            false, default_z, "Z", cmd);
  TCLAP::ValueArg<int> learn_until(
      "", "learn-until",
      "After frame N the maps judge without learning: built from frames 1-N, they judge the rest "
      "as they were (default 0: they learn throughout)",
      false, 0, "N", cmd);
  TCLAP::ValueArg<double> reduction("", "view-reduction",
                                    "Space reference views N times wider than configured: the "
                                    "thesis's R2 and R4 experiments (fig. 4.13) use 2 and 4",
                                    false, 1.0, "N", cmd);
  TCLAP::ValueArg<std::string> compare_views(
      "", "compare-views",
      "Also run maps with reference views N times sparser, e.g. 2,4 (fig. 4.13's R2 and R4)", false,
      "", "N,M", cmd);
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
  // Without ground truth the rawlog's own poses (novelty-import, novelty-poses) are the default.
  a.pose_source = pose_source.isSet() || truth.isSet() ? pose_source.getValue() : "rawlog";
  a.reduction = reduction.getValue();
  a.z = z.getValue();
  a.learn_until = learn_until.getValue();
  if (a.learn_until < 0) throw std::invalid_argument("--learn-until must be >= 0");
  if (!(a.z >= 0.0 && a.z < 1e6)) throw std::invalid_argument("--novelty-z must be in [0, 1e6)");
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
  // An existing file there must be an appearance map (an earlier one, or --map-in continued);
  // the default, inside OUT, is OutputFolder's to check.
  if (map_out.isSet())
    apps::CheckOutputFile(
        "--map-out", a.map_out, {a.rawlog, a.truth, a.config, a.objects_in},
        [](const std::string& p) { return mrpt_plugins::IsMapFileOf(p, "CAppearanceMap"); });
  return a;
}

int Run(int argc, char** argv) {
  const RunArgs a = ParseArgs(argc, argv);
  experiments::SurpriseExperimentOptions o;
  o.rawlog = a.rawlog;
  o.groundtruth = a.truth;
  o.config = a.config;
  o.map_in = a.map_in;
  o.objects_in = a.objects_in;
  o.max_frames = a.max_frames;
  o.panels_every = a.panels_every;
  o.objects_from = a.objects_from;
  o.pose_source = a.pose_source;
  o.view_reduction = a.reduction;
  o.verdict.z = a.z;
  o.learn_until = a.learn_until;
  o.compare_views = experiments::ParseViewFactors(a.compare_views);
  o.console = &std::cout;
  o.status = [](const std::string& line) {
    std::fprintf(stderr, "novelty-run: %s\n", line.c_str());
  };
  std::optional<apps::Progress> progress;
  o.progress = [&](int frame, int total) {
    if (!progress) progress.emplace("novelty-run: playing", total);
    progress->Update(frame);
  };
  // Results go to OUT.partial, renamed at the end; the map too when it goes inside OUT.
  apps::OutputFolder folder("novelty-run", a.out,
                            {a.rawlog, a.truth, a.config, a.map_in, a.objects_in});
  const bool map_inside = a.map_out.rfind(a.out + "/", 0) == 0;
  o.map_out = map_inside ? folder.path() + a.map_out.substr(a.out.size()) : a.map_out;

  const experiments::SurpriseExperimentResult r =
      experiments::RunSurpriseExperiment(o, folder.path());
  if (progress) progress->Finish();
  folder.Commit();
  std::fputs(experiments::SurpriseRunSummary(r, folder.final_path(), a.map_out).c_str(), stdout);
  return r.ended_early ? apps::kExitPartial : apps::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-run", [&] { return Run(argc, argv); });
}
