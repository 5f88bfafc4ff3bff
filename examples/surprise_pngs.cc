// surprise_pngs RAWLOG MAPS.ini OUT_DIR: the appearance map's surprise, every tenth frame a PNG.
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRobotPose.h>

#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>

#include "mrpt_plugins/c_appearance_map.h"
#include "mrpt_plugins/multi_map_config.h"
#include "sensors/rawlog/rawlog_input.h"

int main(int argc, char** argv) try {
  if (argc != 4) throw std::invalid_argument("usage: surprise_pngs RAWLOG MAPS.ini OUT_DIR");
  const std::string rawlog = argv[1], ini = argv[2], out = argv[3];
  mrpt::maps::CMultiMetricMap maps;  // a misspelt class, section or key is an error naming it
  maps.setListOfMaps(novelty::mrpt_plugins::LoadMultiMapConfig(ini));
  const auto appearance = maps.mapByClass<novelty::mrpt_plugins::CAppearanceMap>();
  if (!appearance) throw std::runtime_error(ini + ": declares no CAppearanceMap");
  novelty::sensors::RawlogInput input(rawlog);  // also finds the rawlog's external images
  std::optional<mrpt::poses::CPose3D> robot;    // the latest robot pose before each frame
  int frame = 0;
  while (const auto object = input.Next()) {
    if (const auto o = std::dynamic_pointer_cast<mrpt::obs::CObservationRobotPose>(object))
      robot = o->pose.mean;  // novelty-poses writes these (LED tracker, visual odometry)
    if (const auto o = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(object))
      robot = mrpt::poses::CPose3D(o->odometry);  // wheel odometry: it drifts
    const auto rgbd = std::dynamic_pointer_cast<mrpt::obs::CObservation3DRangeScan>(object);
    if (!rgbd || !robot) continue;
    maps.insertObservation(*rgbd, *robot);  // the robot's pose; the camera is at robot + sensorPose
    if (++frame % 10 == 0)
      appearance->surpriseImage().saveToFile(out + "/surprise_" + std::to_string(frame) + ".png");
  }
  std::printf("%d frames into the maps; surprise PNGs in %s\n", frame, out.c_str());
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "surprise_pngs: %s\n", e.what());
  return 1;
}
