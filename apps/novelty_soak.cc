// novelty-soak: a long run's memory (experiments/soak_experiment.h). Plays a rawlog into the maps
// again and again and samples resident memory and the map's size:
//
//   novelty-soak --rawlog R.rawlog --groundtruth DIR --out OUT [--frames 10000]
//                [--sample-every 100] [--config maps.ini]
//
// OUT: soak.csv (frame, resident MiB, views, map MiB), findings.csv and soak.html (the curves).
// Exit 0 when memory stayed flat once the map stopped growing, 1 when not (or on an error), 2 on
// a bad command line.
#include <tclap/CmdLine.h>

#include <cstdio>

#include "apps/command_line.h"
#include "apps/shell/output_folder.h"
#include "apps/shell/program.h"
#include "apps/shell/progress.h"
#include "experiments/soak_experiment.h"

using namespace novelty;

namespace {

int Run(int argc, char** argv) {
  apps::CommandLine cmd("Memory of a long run: a rawlog played into the maps in a loop.", "0.1");
  TCLAP::ValueArg<std::string> rawlog("", "rawlog", "RGB-D rawlog", true, "", "R.rawlog", cmd);
  TCLAP::ValueArg<std::string> truth("", "groundtruth", "Ground-truth folder (poses)", true, "",
                                     "DIR", cmd);
  TCLAP::ValueArg<std::string> out("", "out", "Output folder", true, "", "OUT", cmd);
  const experiments::SoakOptions defaults;
  TCLAP::ValueArg<int> frames("", "frames", "Frames in all (1…10⁷)", false, defaults.frames, "N",
                              cmd);
  TCLAP::ValueArg<int> every("", "sample-every", "Frames between samples", false,
                             defaults.sample_every, "K", cmd);
  TCLAP::ValueArg<std::string> config("", "config", "Multimap .ini (default: one map of each)",
                                      false, "", "maps.ini", cmd);
  cmd.Parse(argc, argv);
  experiments::SoakOptions o;
  o.rawlog = rawlog.getValue();
  o.groundtruth = truth.getValue();
  o.config = config.getValue();
  o.frames = frames.getValue();
  o.sample_every = every.getValue();
  if (o.frames < 1 || o.frames > 10000000) throw apps::UsageError("--frames must be in 1…10000000");
  if (o.sample_every < 1) throw apps::UsageError("--sample-every must be >= 1");
  apps::OutputFolder folder("novelty-soak", out.getValue(), {o.rawlog, o.groundtruth, o.config});
  apps::Progress progress("[novelty-soak] playing", o.frames);
  o.progress = [&](int played, int) { progress.Update(played); };

  const experiments::SoakResult r = experiments::RunSoak(o);
  progress.Finish();
  experiments::WriteSoakReport(r, folder.path());
  folder.Commit();  // the samples are results also when the memory grew
  std::printf("%d frames in %d loops; resident %.1f MiB at the first sample, %.1f at the end\n",
              r.played, r.loops, r.samples.front().resident_mb, r.samples.back().resident_mb);
  for (const eval::FindingRow& f : r.findings.rows())
    std::printf("  %s: %s%s\n", f.what.c_str(), f.value.c_str(),
                f.holds ? (*f.holds ? " ✓" : " ✗") : "");
  std::printf("  %s/soak.csv, findings.csv, soak.html\n", folder.final_path().c_str());
  if (r.flat()) return apps::kExitOk;
  std::fprintf(stderr, "novelty-soak: %s\n",
               r.plateau.reached ? "resident memory grew over the plateau by more than the bound"
                                 : "the map was still growing at the end: no plateau to judge");
  return apps::kExitFailed;
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-soak", [&] { return Run(argc, argv); });
}
