#include "experiments/soak_experiment.h"

#include <mrpt/maps/CMultiMetricMap.h>

#include <fstream>
#include <opencv2/core.hpp>
#include <stdexcept>

#include "core/range_check.h"
#include "core/resident_memory.h"
#include "eval/html_report.h"
#include "experiments/maps_config.h"
#include "mrpt_plugins/c_appearance_map.h"
#include "mrpt_plugins/multi_map_config.h"
#include "mrpt_plugins/rawlog_map_player.h"
#include "sim/output/ground_truth_reader.h"

namespace novelty::experiments {
namespace {

void AddFindings(SoakResult& r) {
  const eval::MemoryPlateau& p = r.plateau;
  eval::FindingsTable& f = r.findings;
  f.Add("frames played", std::to_string(r.played));
  f.Add("loops of the rawlog", std::to_string(r.loops));
  f.Add("the map stopped growing", p.reached ? "at frame " + std::to_string(p.frame) : "no",
        "before the last sample", p.reached);
  if (p.reached)
    f.Add("resident memory's growth over the plateau",
          cv::format("%+.2f %% (%.1f to %.1f MiB)", 100 * p.growth, p.start_mb, p.end_mb),
          cv::format("< %.0f %%", 100 * kMaxSoakGrowth), p.growth < kMaxSoakGrowth);
  f.Add("reference views at the end", std::to_string(r.samples.back().views));
}

}  // namespace

SoakResult RunSoak(const SoakOptions& o) {
  core::CheckInRange(o.frames, 1, 10000000, "frames");
  core::CheckInRange(o.sample_every, 1, 10000000, "sample_every");
  mrpt::maps::CMultiMetricMap maps;
  const MapsConfig config = OpenMapsConfig(o.config);
  maps.setListOfMaps(mrpt_plugins::LoadMultiMapConfig(*config.ini, "map", config.source));
  const auto appearance = maps.mapByClass<mrpt_plugins::CAppearanceMap>();
  if (!appearance) throw std::runtime_error(config.source + ": holds no CAppearanceMap");
  const sim::GroundTruthReader ground_truth(o.groundtruth);
  SoakResult r;
  while (r.played < o.frames) {
    mrpt_plugins::RawlogMapPlayer player(o.rawlog, mrpt_plugins::PoseSource::kGroundTruth,
                                         ground_truth.CameraPoses());
    int index = 0, in_loop = 0;
    while (r.played < o.frames && player.Next(maps, index)) {
      ++r.played;
      ++in_loop;
      if (r.played % o.sample_every == 0 || r.played == o.frames) {
        const auto& store = appearance->map().store();
        r.samples.push_back({r.played, core::ResidentMegabytes(), store.size()});
        r.map_mb.push_back(double(store.BytesUsed()) / (1 << 20));
      }
      if (o.progress) o.progress(r.played, o.frames);
    }
    if (in_loop == 0) throw std::runtime_error(o.rawlog + ": no frame was inserted into the maps");
    ++r.loops;
  }
  r.plateau = eval::FindMemoryPlateau(r.samples);
  AddFindings(r);
  return r;
}

void WriteSoakReport(const SoakResult& r, const std::string& dir) {
  std::ofstream csv(dir + "/soak.csv");
  csv << "frame,resident_mb,views,map_mb\n";
  eval::PlotSeries rss{"resident memory (MiB)", "#c0392b", {}, 0.0},
      views{"reference views", "#2471a3", {}, 0.0}, map{"map planes (MiB)", "#27ae60", {}, 0.0};
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    const eval::SoakSample& s = r.samples[i];
    csv << s.frame << "," << s.resident_mb << "," << s.views << "," << r.map_mb[i] << "\n";
    rss.points.push_back({double(s.frame), s.resident_mb});
    map.points.push_back({double(s.frame), r.map_mb[i]});
    views.points.push_back({double(s.frame), double(s.views)});
  }
  if (!csv) throw std::runtime_error(dir + "/soak.csv: cannot write it");
  r.findings.WriteCsv(dir + "/findings.csv");
  const eval::MemoryPlateau& p = r.plateau;
  eval::HtmlReport report("novelty-soak");
  report.Paragraph(p.reached ? "The map stopped growing at frame " + std::to_string(p.frame) +
                                   "; resident memory from there: " + std::to_string(p.start_mb) +
                                   " → " + std::to_string(p.end_mb) + " MiB (" +
                                   std::to_string(100 * p.growth) + " %, bound 5 %)."
                             : "The map was still growing at the end: no plateau.");
  r.findings.AddTo(report);
  report.Raw(eval::SvgLinePlot("Memory over the run", "frame", "MiB", {rss, map},
                               {{double(p.frame), double(r.samples.back().frame), "plateau"}}));
  report.Raw(eval::SvgLinePlot("Map size", "frame", "views", {views}));
  report.Save(dir + "/soak.html");
}

}  // namespace novelty::experiments
