// Test helper: a scenario given as text run by the simulator into a fresh folder of the temp
// directory (rawlog, images, ground truth), as novelty-sim writes them. Each caller names its own
// folder: ctest runs tests in parallel processes.
#pragma once

#include <filesystem>
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

}  // namespace novelty::sim
