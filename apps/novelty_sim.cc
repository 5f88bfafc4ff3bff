// novelty-sim SCENARIO --out DIR [--frames N] [--seed S] [--cdnet]
// Plays a scenario file (share/scenarios/*.scn) in the simulator and writes DIR/<name>.rawlog
// (MRPT observations format, images in DIR/<name>_Images/), DIR/groundtruth/ and a contact sheet;
// with --cdnet, a fixed camera's frames and foreground ground truth in CDnet's layout too.
#include <tclap/CmdLine.h>

#include <cstdio>

#include "apps/command_line.h"
#include "apps/shell/output_folder.h"
#include "apps/shell/program.h"
#include "sim/scenario/scenario_parser.h"
#include "sim/scenario/scenario_runner.h"

namespace {

int Run(int argc, char** argv) {
  novelty::sim::RunOptions options;
  novelty::apps::CommandLine cmd(
      "Simulates a NoveltyMaps scenario and writes an MRPT rawlog with ground truth.", "0.1");
  TCLAP::UnlabeledValueArg<std::string> scenario("scenario", "Scenario file (.scn)", true, "",
                                                 "SCENARIO", cmd);
  TCLAP::ValueArg<std::string> out("o", "out", "Output directory", true, "", "DIR", cmd);
  TCLAP::ValueArg<int> frames("n", "frames", "Write only the first N frames", false, 0, "N", cmd);
  TCLAP::ValueArg<long long> seed("s", "seed", "Random seed (sensor and tracker noise)", false, 0,
                                  "S", cmd);
  TCLAP::SwitchArg quiet("q", "quiet", "No progress on stderr", cmd);
  TCLAP::SwitchArg cdnet(
      "", "cdnet",
      "Also write DIR/<name>_cdnet/ in CDnet's layout (input/, groundtruth/ with "
      "motion, shadow and unknown labels, ROI.bmp, temporalROI.txt); fixed "
      "cameras only",
      cmd);
  cmd.Parse(argc, argv);
  // Written into OUT.partial and renamed: a failed or repeated run never mixes frames of two.
  novelty::apps::OutputFolder folder("novelty-sim", out.getValue(), {scenario.getValue()});
  options.out_dir = folder.path();
  if (frames.isSet()) options.frames = frames.getValue();
  if (seed.isSet()) options.seed = static_cast<std::uint64_t>(seed.getValue());
  options.progress = !quiet.getValue();
  options.cdnet = cdnet.getValue();

  const novelty::sim::Scenario loaded = novelty::sim::LoadScenario(scenario.getValue());
  const novelty::sim::RunSummary s = novelty::sim::RunScenario(loaded, options);
  folder.Commit();
  const std::string at = folder.final_path() + "/" + loaded.name;
  std::printf(
      "%s: %d frames, %d observations in %.1f s\n  rawlog: %s.rawlog\n  contact sheet: "
      "%s_contact_sheet.png\n",
      loaded.name.c_str(), s.frames, s.observations, s.seconds, at.c_str(), at.c_str());
  if (options.cdnet) std::printf("  CDnet layout: %s_cdnet/\n", at.c_str());
  return novelty::apps::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-sim", [&] { return Run(argc, argv); });
}
