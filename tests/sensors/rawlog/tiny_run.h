// Test helper: a tiny simulated RGB-D run (six 64×48 frames, external images) as a rawlog.
#pragma once

#include <filesystem>
#include <string>

#include "tests/sim/scenario/simulated_run.h"

namespace novelty::sensors {

// A tiny run in the temp folder novelty_rawlog_reader_<name>.
inline std::filesystem::path SimulateTinyRun(const std::string& name) {
  return sim::SimulateIntoTempFolder(R"(
name tiny
frames 6
fps 5
camera 64 48 60
rig rgbd
material wood phong 0.5 0.3 0.1
object table box 1.0 0.6 0.70 wood at 0 0 fixed
lamp l1 0.5 -0.5 2.5 1.5 1.5 1.5
arc 0 0 1.5 -100 -80 0.1
)",
                                     "novelty_rawlog_reader_" + name);
}

}  // namespace novelty::sensors
