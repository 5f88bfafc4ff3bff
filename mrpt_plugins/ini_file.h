// `.ini` files as the maps read them: opened with the lines MRPT's parser would skip in silence
// refused (so a typo never drops options), and named in errors.
#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <memory>
#include <string>

namespace novelty::mrpt_plugins {

/// The file behind `config` (a CConfigFile), else "map definition": how errors name it.
std::string ConfigSourceName(const mrpt::config::CConfigFileBase& config);

/// Throws std::runtime_error "PATH:LINE: …" for `.ini` text with lines MRPT's parser would skip
/// in silence (an unclosed "[section", a line without '=', a key before any section), or
/// "PATH: not a text .ini file" for binary content.
void CheckIniText(const std::string& content, const std::string& path);

/// Opens an `.ini` file; throws std::runtime_error naming a missing file, one that is not text
/// (CheckIniText), or one MRPT cannot parse.
std::unique_ptr<mrpt::config::CConfigFileBase> OpenConfigFile(const std::string& path);

/// The value part of an `.ini` line: inline comments (after ';', '#' or "//") and the blanks around
/// removed.
std::string StripIniComment(std::string text);

}  // namespace novelty::mrpt_plugins
