// A long run's memory (beyond the thesis: a robot drives the same route all day). A rawlog is
// played into the maps again and again, and resident memory and the map's size are sampled. Once
// the map has stopped growing (no new reference view: it is bounded by the explored space, not by
// time), resident memory must stay flat: less than kMaxSoakGrowth from there to the end.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "eval/findings_table.h"
#include "eval/memory_plateau.h"

namespace novelty::experiments {

/// The bound on resident memory's growth over the plateau (the reliability issue's).
inline constexpr double kMaxSoakGrowth = 0.05;

struct SoakOptions {
  std::string rawlog;       ///< an RGB-D rawlog
  std::string groundtruth;  ///< novelty-sim's folder: the camera poses
  /// A CMultiMetricMap .ini with a CAppearanceMap; empty: one CAppearanceMap and one
  /// CDifferencingMap with their defaults.
  std::string config;
  int frames = 10000;      ///< frames in all, over as many loops as that takes (1 … 10⁷)
  int sample_every = 100;  ///< frames between samples (and the last frame)
  /// Told the frames played so far and the total.
  std::function<void(int played, int total)> progress;
};

struct SoakResult {
  std::vector<eval::SoakSample> samples;
  std::vector<double> map_mb;  ///< the map's planes at each sample (MiB)
  eval::MemoryPlateau plateau;
  int played = 0, loops = 0;
  eval::FindingsTable findings;
  /// The plateau was reached and resident memory grew less than kMaxSoakGrowth over it.
  bool flat() const { return plateau.reached && plateau.growth < kMaxSoakGrowth; }
};

/// Runs the soak; throws std::invalid_argument for options out of range and std::runtime_error
/// naming the rawlog when no frame of it reaches the maps.
SoakResult RunSoak(const SoakOptions& options);

/// soak.csv (frame, resident MiB, views, map MiB), findings.csv and soak.html (the curves) in
/// `dir`.
void WriteSoakReport(const SoakResult& result, const std::string& dir);

}  // namespace novelty::experiments
