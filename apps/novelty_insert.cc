// novelty-insert: a synthetic box drawn into a real RGB-D recording from one frame on, with its
// depth and the real scene's occlusion, then played into the maps with the box's masks as ground
// truth: surprise against image differencing on real data (experiments/inserted_object_run.h).
//
//   novelty-insert --rawlog R.rawlog --out OUT [--from N] [--standoff 0.3] [--size 0.3]
//       [--config INI] [--frames N] [--panels-every 10] [--judge-only]
//
// R: RGB-D frames with a pose observation each (novelty-import writes such). OUT gets
// inserted.rawlog (+ _Images), groundtruth/, run/ (novelty-run's output: panels, report.html,
// metrics.csv with the box's AS and PAS per frame) and findings.csv; all into OUT.partial,
// renamed at the end.
//
// Exit status: 0 done; 1 an error (one line on stderr, nothing published); 2 bad command line.
#include <tclap/CmdLine.h>

#include <cstdio>
#include <optional>
#include <string>

#include "apps/command_line.h"
#include "apps/shell/output_folder.h"
#include "apps/shell/program.h"
#include "apps/shell/progress.h"
#include "experiments/inserted_object_run.h"

namespace {

using namespace novelty;

int Run(int argc, char** argv) {
  apps::CommandLine cmd(
      "Draws a synthetic box into a real RGB-D rawlog and scores surprise against differencing "
      "on it.",
      "0.1");
  TCLAP::ValueArg<std::string> rawlog("", "rawlog", "RGB-D rawlog with poses", true, "", "R", cmd);
  TCLAP::ValueArg<std::string> out("", "out", "Output folder", true, "", "OUT", cmd);
  TCLAP::ValueArg<int> from("", "from", "First frame with the box (default: the middle one)", false,
                            0, "N", cmd);
  TCLAP::ValueArg<double> standoff(
      "", "standoff", "Metres in front of the surface that frame sees at its centre (default 0.3)",
      false, 0.3, "M", cmd);
  TCLAP::ValueArg<double> size("", "size", "The box's edge length, m (default 0.3)", false, 0.3,
                               "M", cmd);
  TCLAP::ValueArg<std::string> config(
      "", "config", "The maps .ini (must declare a CDifferencingMap; default: both maps)", false,
      "", "INI", cmd);
  TCLAP::SwitchArg judge_only(
      "", "judge-only",
      "The maps learn from the frames before the box only and judge the rest as they were "
      "(default: they learn throughout, as a robot's do)",
      cmd);
  TCLAP::ValueArg<int> frames("", "frames", "Only the first N frames", false, 0, "N", cmd);
  TCLAP::ValueArg<int> panels("", "panels-every", "A panel every K-th frame (default 10)", false,
                              10, "K", cmd);
  cmd.Parse(argc, argv);
  experiments::InsertedObjectRunOptions o;
  o.rawlog = rawlog.getValue();
  o.config = config.getValue();
  o.insert_from = from.getValue();
  o.standoff = standoff.getValue();
  o.size.setConstant(size.getValue());
  if (frames.isSet()) o.max_frames = frames.getValue();
  o.panels_every = panels.getValue();
  o.judge_only = judge_only.getValue();
  if (o.insert_from < 0 || o.insert_from == 1)
    throw apps::UsageError("--from must be 2 or more: the maps learn from the frames before");
  if (o.max_frames && *o.max_frames < 2) throw apps::UsageError("--frames must be >= 2");
  if (o.panels_every < 1) throw apps::UsageError("--panels-every must be >= 1");
  o.status = [](const std::string& line) {
    std::fprintf(stderr, "novelty-insert: %s\n", line.c_str());
  };
  std::optional<apps::Progress> progress;
  std::string stage;
  o.progress = [&](const std::string& what, int frame, int total) {
    if (what != stage) {
      if (progress) progress->Finish();
      progress.emplace("novelty-insert: " + what, total);
      stage = what;
    }
    progress->Update(frame);
  };
  apps::OutputFolder folder("novelty-insert", out.getValue(), {o.rawlog, o.config});
  experiments::InsertedObjectRunResult r = experiments::RunInsertedObject(o, folder.path());
  if (progress) progress->Finish();
  folder.Commit();
  std::printf("%d frames, the box from frame %d, seen in %d (%.0f pixels on average)\n", r.frames,
              r.insert_from, r.box_frames, r.box_pixels);
  for (const auto& f : r.findings.rows())
    std::printf("  %-48s %-26s %s %s\n", f.what.c_str(), f.value.c_str(), f.target.c_str(),
                eval::HoldsText(f.holds).c_str());
  std::printf("  %s\n  results: %s\n", r.run.verdict_sentence.c_str(), folder.final_path().c_str());
  return apps::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-insert", [&] { return Run(argc, argv); });
}
