// novelty-find-objects: which known objects an image, a folder of images or a rawlog shows, and
// where (experiments/object_finder_run.h) — no ground truth.
//
//   novelty-find-objects INPUT --objects DB --out OUT [--min-matches 10] [--max-panels 50]
//       [--camera-file FILE | --fx FX --fy FY --cx CX --cy CY] [--include GLOB] [--exclude GLOB]
//
// DB is an object database (novelty-learn-objects, or novelty-run's map.object_database). OUT
// gets found.csv (a row per frame and object found), objects.csv (per object: frames found and
// verified, first and last) and panels/ (the frames with outlines). Each object found is printed.
#include <tclap/CmdLine.h>

#include <cstdio>
#include <optional>
#include <string>

#include "apps/command_line.h"
#include "apps/shell/output_folder.h"
#include "apps/shell/program.h"
#include "apps/shell/progress.h"
#include "eval/skipped_frames.h"
#include "experiments/object_finder_run.h"
#include "sensors/dataset/camera_file.h"

using namespace novelty;

namespace {

int Run(int argc, char** argv) {
  apps::CommandLine cmd("Finds known objects in images or a rawlog and lists them (thesis ch. 5)",
                        "0.1");
  TCLAP::UnlabeledValueArg<std::string> in("input", "An image, a folder of images or a .rawlog",
                                           true, "", "INPUT", cmd);
  TCLAP::ValueArg<std::string> db("", "objects", "The object database", true, "", "DB", cmd);
  TCLAP::ValueArg<std::string> out("o", "out", "Output folder", true, "", "OUT", cmd);
  experiments::ObjectFinderRunOptions o;
  TCLAP::ValueArg<int> min_matches(
      "", "min-matches", "List an object not verified from this many matches (default 10)", false,
      o.finder.min_matches, "N", cmd);
  TCLAP::ValueArg<int> max_panels("", "max-panels", "Panels written at most (default 50)", false,
                                  o.max_panels, "N", cmd);
  TCLAP::ValueArg<std::string> camera_file(
      "", "camera-file",
      "Images' intrinsics: ROS camera_info YAML or MRPT camera .ini (default nominal: focal "
      "length the larger side); a rawlog brings its own",
      false, "", "FILE", cmd);
  TCLAP::MultiArg<std::string> include("", "include", "In a folder, only files matching GLOB",
                                       false, "GLOB", cmd);
  TCLAP::MultiArg<std::string> exclude("", "exclude", "In a folder, not files matching GLOB", false,
                                       "GLOB", cmd);
  cmd.Parse(argc, argv);
  if (min_matches.getValue() < 1) throw apps::UsageError("--min-matches must be >= 1");
  if (max_panels.getValue() < 0) throw apps::UsageError("--max-panels must be >= 0");
  o.database = db.getValue();
  o.input = in.getValue();
  o.finder.min_matches = min_matches.getValue();
  o.max_panels = max_panels.getValue();
  o.pick = {include.getValue(), exclude.getValue()};
  if (camera_file.isSet()) o.camera = sensors::ReadCameraFile(camera_file.getValue());
  o.console = stdout;
  std::optional<apps::Progress> progress;
  o.progress = [&](int done, int total) {
    if (total <= 1) return;
    if (!progress) progress.emplace("[novelty-find-objects] frames", total);
    progress->Update(done);
  };
  apps::OutputFolder folder("novelty-find-objects", out.getValue(), {o.input, o.database});
  const experiments::ObjectFinderRunResult r = experiments::RunObjectFinder(o, folder.path());
  if (progress) progress->Finish();
  folder.Commit();
  if (r.skipped)
    std::fprintf(stderr, "[novelty-find-objects] %s\n",
                 eval::SkippedFramesSummary(r.frames + r.skipped, r.skip_reasons).c_str());
  if (!r.stopped_by.empty())
    std::fprintf(stderr, "[novelty-find-objects] %s ends early: %s\n", o.input.c_str(),
                 r.stopped_by.c_str());
  std::printf("%d frames searched (%d skipped), %zu objects found", r.frames, r.skipped,
              r.objects.size());
  for (const auto& [name, s] : r.objects)
    std::printf("%s %s in %d (verified %d)", name == r.objects.begin()->first ? ":" : ",",
                name.c_str(), s.frames, s.verified);
  std::printf("\n→ %s/found.csv\n", folder.final_path().c_str());
  return r.stopped_by.empty() ? apps::kExitOk : apps::kExitPartial;
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-find-objects", [&] { return Run(argc, argv); });
}
