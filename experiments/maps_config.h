// The maps' .ini of an experiment: the user's file, or the maps the experiments declare when none
// is given — one CAppearanceMap and one CDifferencingMap at their defaults, the maps of
// share/novelty_run.ini (tested equal).
#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <memory>
#include <string>

namespace novelty::experiments {

struct MapsConfig {
  std::unique_ptr<mrpt::config::CConfigFileBase> ini;
  std::string source;  ///< the file's path, or "the default maps": for error messages
};

/// `path` (checked to be a readable text file, mrpt_plugins::OpenConfigFile), or the default maps
/// when `path` is empty.
MapsConfig OpenMapsConfig(const std::string& path);

}  // namespace novelty::experiments
