// AppearanceMapOptions from an MRPT configuration file section (share/appearance.ini documents
// every key and its default). Unknown keys and unreadable values are errors that name the file,
// the section and the key: a misspelt option must not silently fall back to a default.
#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <string>

#include "maps/appearance/appearance_map.h"

namespace novelty::mrpt_plugins {

/// Reads `section` of `config` on top of the defaults. `source` names the file in errors.
appearance::AppearanceMapOptions LoadAppearanceMapOptions(
    const mrpt::config::CConfigFileBase& config, const std::string& section,
    const std::string& source);

/// The same from a file path; throws std::runtime_error if it cannot be read.
appearance::AppearanceMapOptions LoadAppearanceMapOptions(
    const std::string& ini_path, const std::string& section = "AppearanceMap");

}  // namespace novelty::mrpt_plugins
