// Plays a scenario and writes what the robot's sensors saw: DIR/<name>.rawlog with images in
// DIR/<name>_Images/, ground truth in DIR/groundtruth/ (see ground_truth_writer.h) and a contact
// sheet DIR/<name>_contact_sheet.png. Progress goes to stderr.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "sim/scenario/scenario.h"

namespace novelty::sim {

struct RunOptions {
  std::string out_dir;
  /// Frames to write (from the first); unset = the scenario's `frames`.
  std::optional<int> frames;
  /// Overrides the scenario's seed (sensor noise, tracker noise and dropouts).
  std::optional<std::uint64_t> seed;
  /// Report progress on stderr.
  bool progress = true;
  /// Tiles on the contact sheet (evenly spaced frames).
  int contact_sheet_tiles = 24;
  /// Also write the frames with foreground/shadow ground truth in CDnet's layout to
  /// DIR/<name>_cdnet/ (sim/output/cdnet_writer.h). The temporal ROI is the frames of the
  /// scenario's phases after the first (the first phase learns the background), or every frame
  /// without two phases. Fixed cameras only (std::invalid_argument for a robot's).
  bool cdnet = false;
};

struct RunSummary {
  int frames = 0;
  int observations = 0;
  double seconds = 0.0;  ///< wall-clock time of the run
  std::string rawlog;
  std::string contact_sheet;
  std::string cdnet_dir;  ///< set with RunOptions::cdnet
};

RunSummary RunScenario(const Scenario& scenario, const RunOptions& options);

}  // namespace novelty::sim
