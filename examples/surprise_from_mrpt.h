// The README's example (surprise_from_mrpt.cc).
#pragma once

#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/poses/CPose3D.h>

#include <opencv2/core.hpp>
#include <string>

void LoadMaps(const std::string& ini_file, mrpt::maps::CMultiMetricMap& maps);
cv::Mat Surprise(mrpt::maps::CMultiMetricMap& maps, const mrpt::obs::CObservation3DRangeScan& rgbd,
                 const mrpt::poses::CPose3D& robot_pose);
