// Test helper: a scenario given as text run by the simulator into a fresh folder of the temp
// directory (rawlog, images, ground truth), as novelty-sim writes them. Each caller names its own
// folder: ctest runs tests in parallel processes.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "sim/scenario/scenario_parser.h"
#include "sim/scenario/scenario_runner.h"

namespace novelty::sim {

inline std::filesystem::path SimulateIntoTempFolder(const std::string& scenario_text,
                                                    const std::string& folder) {
  std::istringstream in(scenario_text);
  const Scenario s = ParseScenario(in, folder + ".scn");
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / folder;
  std::filesystem::remove_all(dir);
  RunOptions o;
  o.out_dir = dir.string();
  o.progress = false;
  RunScenario(s, o);
  return dir;
}

/// share/scenarios/glass_and_cup.scn cut to its first `frames` frames, its camera line replaced by
/// `camera` ("camera 80 60 60"), without its events and phases: the room alone, for short runs.
inline std::string GlassAndCupRoom(int frames, const std::string& camera) {
  std::ifstream in(std::string(NOVELTY_SOURCE_DIR) + "/share/scenarios/glass_and_cup.scn");
  std::ostringstream out;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("frames ", 0) == 0) line = "frames " + std::to_string(frames);
    if (line.rfind("camera ", 0) == 0) line = camera;
    if (line.rfind("event", 0) == 0 || line.rfind("phase", 0) == 0) continue;
    out << line << "\n";
  }
  return out.str();
}

}  // namespace novelty::sim
