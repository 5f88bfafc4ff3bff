// surprise_from_rawlog: NoveltyMaps in your own MRPT program, built against the installed package
// (examples/CMakeLists.txt). Plays an RGB-D rawlog into the maps of a CMultiMetricMap .ini through
// insertObservation, writes the surprise of every tenth frame as a PNG, saves the maps after frame
// K, loads them into a second CMultiMetricMap and plays the rest into both: the loaded maps must
// give the surprise of the ones that never stopped, over the same pixels and within 1 % (map files
// store the planes rounded to what the surprise can tell apart: docs/map_storage.md; exit 1 if
// not).
//
//   surprise_from_rawlog RAWLOG MAPS.ini OUT_DIR [K=20]
//
// The robot pose is the latest CObservationRobotPose (novelty-poses writes them from the LED
// tracker) or CObservationOdometry (wheel odometry: it drifts) before each RGB-D observation.
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRobotPose.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

#include "mrpt_plugins/c_appearance_map.h"
#include "mrpt_plugins/map_file.h"
#include "mrpt_plugins/multi_map_config.h"
#include "sensors/rawlog/rawlog_input.h"

using novelty::mrpt_plugins::CAppearanceMap;

// The same pixels predicted (NaN where not) and a relative L1 difference within 1 %.
bool Close(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size() || a.type() != CV_32FC1 || b.type() != CV_32FC1) return false;
  double difference = 0.0, total = 0.0;
  for (int i = 0; i < a.rows * a.cols; ++i) {
    const float x = a.at<float>(i), y = b.at<float>(i);
    if (std::isnan(x) != std::isnan(y)) return false;
    if (std::isnan(x)) continue;
    difference += std::abs(x - y);
    total += std::abs(x);
  }
  return difference <= 0.01 * total;
}

int Play(const std::string& rawlog, const std::string& ini, const std::string& out, int k) {
  // The maps an .ini declares (examples/maps.ini: a CAppearanceMap and a CDifferencingMap);
  // a misspelt class, section or key is an error naming the file, section and key.
  mrpt::maps::CMultiMetricMap maps, resumed;
  maps.setListOfMaps(novelty::mrpt_plugins::LoadMultiMapConfig(ini));
  novelty::sensors::RawlogInput input(rawlog);  // also finds the rawlog's external images
  std::optional<mrpt::poses::CPose3D> robot;
  int frame = 0, matching = 0;
  while (const auto object = input.Next()) {
    if (const auto o = std::dynamic_pointer_cast<mrpt::obs::CObservationRobotPose>(object))
      robot = o->pose.mean;
    if (const auto o = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(object))
      robot = mrpt::poses::CPose3D(o->odometry);
    const auto rgbd = std::dynamic_pointer_cast<mrpt::obs::CObservation3DRangeScan>(object);
    if (!rgbd || !robot) continue;
    ++frame;
    maps.insertObservation(*rgbd, *robot);  // the ROBOT's pose: the camera is at robot ⊕ sensorPose
    const auto& map = *maps.mapByClass<CAppearanceMap>();
    if (frame % 10 == 0)
      map.surpriseImage().saveToFile(out + "/surprise_" + std::to_string(frame) + ".png");
    if (frame == k) {  // saved atomically; loading checks the file and names it on error
      novelty::mrpt_plugins::SaveAtomically(maps, out + "/maps.bin");
      novelty::mrpt_plugins::LoadInto(resumed, out + "/maps.bin", "CMultiMetricMap");
    } else if (frame > k) {
      resumed.insertObservation(*rgbd, *robot);
      matching += Close(map.lastProducts().surprise,
                        resumed.mapByClass<CAppearanceMap>()->lastProducts().surprise);
    }
  }
  std::printf(
      "%d frames; after loading the maps saved at frame %d, %d of %d frames gave the "
      "surprise of the maps never saved (within 1 %%)\n",
      frame, k, matching, std::max(0, frame - k));
  return frame > k && matching == frame - k ? 0 : 1;
}

int main(int argc, char** argv) {
  if (argc < 4 || argc > 5) {
    std::fprintf(stderr, "usage: %s RAWLOG MAPS.ini OUT_DIR [K=20]\n", argv[0]);
    return 2;
  }
  try {
    std::filesystem::create_directories(argv[3]);
    return Play(argv[1], argv[2], argv[3], argc == 5 ? std::stoi(argv[4]) : 20);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
    return 2;
  }
}
