#include "experiments/maps_config.h"

#include <mrpt/config/CConfigFileMemory.h>

#include "mrpt_plugins/ini_file.h"

namespace novelty::experiments {

MapsConfig OpenMapsConfig(const std::string& path) {
  if (!path.empty()) return {mrpt_plugins::OpenConfigFile(path), path};
  return {std::make_unique<mrpt::config::CConfigFileMemory>(
              "[map]\nCAppearanceMap_count = 1\nCDifferencingMap_count = 1\n"),
          "the default maps"};
}

}  // namespace novelty::experiments
