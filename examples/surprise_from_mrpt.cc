// The README's example: NoveltyMaps' maps in your own MRPT program. Compiled and run as a test
// (tests/mrpt_plugins/readme_example_test.cc), which also checks that the README quotes this
// code between its markers word for word.
#include "examples/surprise_from_mrpt.h"

// README example begins
#include <mrpt/config/CConfigFile.h>
#include <mrpt/maps/CMultiMetricMap.h>

#include "mrpt_plugins/c_appearance_map.h"
#include "mrpt_plugins/register_maps.h"

// The maps declared in an .ini file (e.g. share/novelty_run.ini: a CAppearanceMap and a
// CDifferencingMap in section [map], their options in [map_<Class>_00_options]).
void LoadMaps(const std::string& ini_file, mrpt::maps::CMultiMetricMap& maps) {
  novelty::mrpt_plugins::RegisterMaps();
  mrpt::maps::TSetOfMetricMapInitializers inits;
  inits.loadFromConfigFile(mrpt::config::CConfigFile(ini_file), "map");
  maps.setListOfMaps(inits);
}

// One RGB-D frame in, its surprise map out (CV_32FC1, NaN where the map has no view yet).
cv::Mat Surprise(mrpt::maps::CMultiMetricMap& maps, const mrpt::obs::CObservation3DRangeScan& rgbd,
                 const mrpt::poses::CPose3D& robot_pose) {
  maps.insertObservation(rgbd, robot_pose);  // the camera is at robot_pose ⊕ rgbd.sensorPose
  return maps.mapByClass<novelty::mrpt_plugins::CAppearanceMap>()->lastProducts().surprise;
}
// README example ends
