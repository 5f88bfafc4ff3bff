// A scenario played in memory for the reference camera only — frames with their true pose,
// depth, object ids and novelty mask — for tests, benchmarks and experiments that need no rawlog
// (RunScenario writes the full sensor set to disk).
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

#include "sim/scenario/scenario.h"

namespace novelty::sim {

struct SimulatedFrame {
  int index = 0;      ///< 1-based
  double time = 0.0;  ///< seconds
  cv::Mat rgb;        ///< CV_8UC3
  cv::Mat depth;      ///< CV_32FC1 metres
  cv::Mat novelty;    ///< CV_8UC1, as in the ground truth (255 added, 128 removed)
  Eigen::Isometry3d T_world_cam = Eigen::Isometry3d::Identity();
};

/// The first `frames` frames (all if ≤ 0) of the scenario at its frame rate.
std::vector<SimulatedFrame> SimulateFrames(const Scenario& scenario, int frames = 0);

}  // namespace novelty::sim
