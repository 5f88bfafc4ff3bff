// novelty-soak: a long run's memory. Plays a rawlog into the maps again and again (the robot
// drives the same route all day) and samples resident memory and the map's size:
//
//   novelty-soak --rawlog R.rawlog --groundtruth DIR --out OUT [--frames 10000]
//                [--sample-every 100] [--config maps.ini]
//
// Once the map has stopped growing (no new reference view: it is bounded by the explored space,
// not by time), resident memory must stay flat: less than 5 % growth from there to the end.
// Writes OUT/soak.csv (frame, resident MiB, views, map MiB) and OUT/soak.html (the curves);
// exit 0 when flat, 1 when not (or on an error), 2 on a bad command line. Progress on stderr.
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <tclap/CmdLine.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "apps/command_line.h"
#include "apps/shell/output_folder.h"
#include "apps/shell/program.h"
#include "apps/shell/progress.h"
#include "core/resident_memory.h"
#include "eval/html_report.h"
#include "eval/memory_plateau.h"
#include "mrpt_plugins/c_appearance_map.h"
#include "mrpt_plugins/multi_map_config.h"
#include "mrpt_plugins/rawlog_map_player.h"
#include "sensors/rawlog/brief_message.h"
#include "sim/output/ground_truth_reader.h"

using namespace novelty;

namespace {

constexpr double kMaxGrowth = 0.05;  // the reliability issue's bound on the plateau's growth

mrpt::maps::TSetOfMetricMapInitializers Maps(const std::string& config) {
  if (!config.empty()) return mrpt_plugins::LoadMultiMapConfig(config);
  return mrpt_plugins::LoadMultiMapConfig(
      mrpt::config::CConfigFileMemory("[map]\nCAppearanceMap_count = 1\n"
                                      "CDifferencingMap_count = 1\n"),
      "map", "default maps");
}

void WriteReport(const std::string& out, const std::vector<eval::SoakSample>& samples,
                 const std::vector<double>& map_mb, const eval::MemoryPlateau& p) {
  std::ofstream csv(out + "/soak.csv");
  csv << "frame,resident_mb,views,map_mb\n";
  eval::PlotSeries rss{"resident memory (MiB)", "#c0392b", {}, 0.0},
      views{"reference views", "#2471a3", {}, 0.0}, map{"map planes (MiB)", "#27ae60", {}, 0.0};
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const eval::SoakSample& s = samples[i];
    csv << s.frame << "," << s.resident_mb << "," << s.views << "," << map_mb[i] << "\n";
    rss.points.push_back({double(s.frame), s.resident_mb});
    map.points.push_back({double(s.frame), map_mb[i]});
    views.points.push_back({double(s.frame), double(s.views)});
  }
  eval::HtmlReport report("novelty-soak");
  report.Paragraph(p.reached ? "The map stopped growing at frame " + std::to_string(p.frame) +
                                   "; resident memory from there: " + std::to_string(p.start_mb) +
                                   " → " + std::to_string(p.end_mb) + " MiB (" +
                                   std::to_string(100 * p.growth) + " %, bound 5 %)."
                             : "The map was still growing at the end: no plateau.");
  report.Raw(eval::SvgLinePlot("Memory over the run", "frame", "MiB", {rss, map},
                               {{double(p.frame), double(samples.back().frame), "plateau"}}));
  report.Raw(eval::SvgLinePlot("Map size", "frame", "views", {views}));
  report.Save(out + "/soak.html");
}

int Run(int argc, char** argv) {
  novelty::apps::CommandLine cmd("Memory of a long run: a rawlog played into the maps in a loop.",
                                 "0.1");
  TCLAP::ValueArg<std::string> rawlog("", "rawlog", "RGB-D rawlog", true, "", "R.rawlog", cmd);
  TCLAP::ValueArg<std::string> truth("", "groundtruth", "Ground-truth folder (poses)", true, "",
                                     "DIR", cmd);
  TCLAP::ValueArg<std::string> out("", "out", "Output folder", true, "", "OUT", cmd);
  TCLAP::ValueArg<int> frames("", "frames", "Frames in all (1…10⁷)", false, 10000, "N", cmd);
  TCLAP::ValueArg<int> every("", "sample-every", "Frames between samples", false, 100, "K", cmd);
  TCLAP::ValueArg<std::string> config("", "config", "Multimap .ini (default: one map of each)",
                                      false, "", "maps.ini", cmd);
  cmd.Parse(argc, argv);
  if (frames.getValue() < 1 || frames.getValue() > 10000000)
    throw std::invalid_argument("--frames must be in 1…10000000");
  if (every.getValue() < 1) throw std::invalid_argument("--sample-every must be >= 1");

  mrpt::maps::CMultiMetricMap maps;
  maps.setListOfMaps(Maps(config.getValue()));
  const auto appearance = maps.mapByClass<mrpt_plugins::CAppearanceMap>();
  if (!appearance) throw std::runtime_error("the maps hold no CAppearanceMap");
  const sim::GroundTruthReader ground_truth(truth.getValue());
  apps::OutputFolder folder("novelty-soak", out.getValue(),
                            {rawlog.getValue(), truth.getValue(), config.getValue()});

  std::vector<eval::SoakSample> samples;
  std::vector<double> map_mb;
  int played = 0, loops = 0;
  apps::Progress progress("[novelty-soak] playing", frames.getValue());
  while (played < frames.getValue()) {
    mrpt_plugins::RawlogMapPlayer player(rawlog.getValue(), mrpt_plugins::PoseSource::kGroundTruth,
                                         ground_truth.CameraPoses());
    int index = 0, in_loop = 0;
    while (played < frames.getValue() && player.Next(maps, index)) {
      ++played;
      ++in_loop;
      if (played % every.getValue() == 0 || played == frames.getValue()) {
        const auto& store = appearance->map().store();
        samples.push_back({played, core::ResidentMegabytes(), store.size()});
        map_mb.push_back(double(store.BytesUsed()) / (1 << 20));
      }
      progress.Update(played);
    }
    if (in_loop == 0)
      throw std::runtime_error(rawlog.getValue() + ": no frame was inserted into the maps");
    ++loops;
  }
  progress.Finish();
  const eval::MemoryPlateau p = eval::FindMemoryPlateau(samples);
  WriteReport(folder.path(), samples, map_mb, p);
  folder.Commit();  // the samples are results also when the memory grew
  std::printf("%d frames in %d loops; resident %.1f MiB at the first sample, %.1f at the end\n",
              played, loops, samples.front().resident_mb, samples.back().resident_mb);
  if (!p.reached) {
    std::printf("the map was still growing at the end (%d views): no plateau\n",
                samples.back().views);
    return 1;
  }
  std::printf(
      "map stopped growing at frame %d (%d views); resident memory from there %.1f → "
      "%.1f MiB (%+.2f %%, bound %.0f %%)\n  %s/soak.csv, %s/soak.html\n",
      p.frame, samples.back().views, p.start_mb, p.end_mb, 100 * p.growth, 100 * kMaxGrowth,
      out.getValue().c_str(), out.getValue().c_str());
  return p.growth < kMaxGrowth ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-soak", [&] { return Run(argc, argv); });
}
