// Test helper: a short simulated arc around a table at 160×120, as RGB-D observations.
#pragma once

#include <sstream>
#include <vector>

#include "sensors/rawlog/rgbd_observation.h"
#include "sim/scenario/scenario_parser.h"
#include "sim/scenario/simulate_frames.h"

namespace novelty::mrpt_plugins {

inline const std::vector<sim::SimulatedFrame>& Frames() {
  static const std::vector<sim::SimulatedFrame> frames = [] {
    std::istringstream in(R"(
name clip
frames 36
fps 7
camera 160 120 60
rig rgbd
mount 0.0 0.0 1.10 90 16
material wood phong 0.45 0.28 0.14 0.1 20
material cloth phong 0.92 0.90 0.84
texture cloth stripes 0.25 0.35 0.70 20
material red phong 0.75 0.10 0.08 0.2 30
object table box 1.2 0.8 0.72 wood at 0 0 fixed
object cloth plane 1.3 0.9 cloth at 0 0 on table
object box box 0.14 0.06 0.20 red at 0.25 0.20 on cloth mass 0.4
lamp l1 -1.0 0.8 2.6 2.2 2.1 1.9
arc 0 0 1.6 -100 -80 0.15
stop 0.5
arc 0 0 1.6 -80 -100 0.15
)");
    return sim::SimulateFrames(sim::ParseScenario(in, "clip.scn"));
  }();
  return frames;
}

// A frame of a clip whose camera has a 60 degree field of view (`camera W H 60`) as an
// observation from a sensor at its true pose, the robot at the origin.
inline mrpt::obs::CObservation3DRangeScan Observation(const sim::SimulatedFrame& f) {
  return sensors::MakeRgbdObservation(
      f.time, f.rgb, f.depth, core::PinholeCamera::FromFov(f.rgb.cols, f.rgb.rows, M_PI / 3),
      f.T_world_cam);
}

}  // namespace novelty::mrpt_plugins
