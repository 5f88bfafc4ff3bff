// AppearanceMapOptions from an MRPT configuration file section (share/appearance.ini documents
// every key and its default). Unknown keys and unreadable values are errors that name the file,
// the section and the key: a misspelt option must not silently fall back to a default.
#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <string>

#include "maps/appearance/appearance_map.h"
#include "mrpt_plugins/depth_source.h"

namespace novelty::mrpt_plugins {

/// Everything a map section configures: the map's options and where camera observations get
/// their depth (depth_source.h).
struct MapConfig {
  appearance::AppearanceMapOptions map;
  DepthSourceOptions depth;
};

/// The file behind `config` (a CConfigFile), else "map definition": how errors name it.
std::string ConfigSourceName(const mrpt::config::CConfigFileBase& config);

/// Reads `section` of `config` on top of the defaults. `source` names the file in errors.
MapConfig LoadMapConfig(const mrpt::config::CConfigFileBase& config, const std::string& section,
                        const std::string& source);
/// The same from a file path; throws std::runtime_error if it cannot be read.
MapConfig LoadMapConfig(const std::string& ini_path, const std::string& section = "AppearanceMap");

/// The map's options alone (see LoadMapConfig).
appearance::AppearanceMapOptions LoadAppearanceMapOptions(
    const mrpt::config::CConfigFileBase& config, const std::string& section,
    const std::string& source);

/// The map's options alone, from a file path.
appearance::AppearanceMapOptions LoadAppearanceMapOptions(
    const std::string& ini_path, const std::string& section = "AppearanceMap");

}  // namespace novelty::mrpt_plugins
