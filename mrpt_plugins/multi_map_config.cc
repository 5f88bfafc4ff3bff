#include "mrpt_plugins/multi_map_config.h"

#include <mrpt/maps/TMetricMapInitializer.h>

#include <cstdio>
#include <memory>
#include <stdexcept>

#include "mrpt_plugins/appearance_map_options.h"
#include "mrpt_plugins/differencing_map_options.h"
#include "mrpt_plugins/illumination_invariant_map_options.h"
#include "mrpt_plugins/object_database_map_options.h"
#include "mrpt_plugins/option_table.h"
#include "mrpt_plugins/register_maps.h"
#include "sensors/rawlog/brief_message.h"

namespace novelty::mrpt_plugins {

namespace {

std::string MapSection(const std::string& section, const std::string& cls, int k,
                       const char* part) {
  char index[16];
  std::snprintf(index, sizeof index, "%02d", k);
  return section + "_" + cls + "_" + index + "_" + part;
}

}  // namespace

std::map<std::string, int> CheckMultiMapConfig(const mrpt::config::CConfigFileBase& ini,
                                               const std::string& section,
                                               const std::string& source,
                                               const std::vector<std::string>& exactly_one) {
  std::vector<std::string> keys, sections;
  ini.getAllKeys(section, keys);
  ini.getAllSections(sections);
  if (keys.empty())
    throw std::runtime_error(source + ": no section [" + section +
                             "] declaring maps (<MapClass>_count = N)");
  std::map<std::string, int> counts;
  for (const std::string& key : keys) {
    const std::string where = source + ": [" + section + "] " + key;
    const auto suffix = key.rfind("_count");
    if (suffix == std::string::npos || suffix + 6 != key.size())
      throw std::runtime_error(where + ": only <MapClass>_count keys belong in [" + section + "]");
    const std::string cls = key.substr(0, suffix);
    const std::string text = StripIniComment(ini.read_string(section, key, ""));
    std::size_t used = 0;
    int n = -1;
    try {
      n = std::stoi(text, &used);
    } catch (const std::exception&) {
    }
    // Each map holds its own reference views: a robot runs a few, not thousands.
    constexpr int kMaxMapsPerClass = 16;
    if (n < 0 || n > kMaxMapsPerClass || used != text.size())
      throw std::runtime_error(where + " = '" + text + "': not a count in 0…" +
                               std::to_string(kMaxMapsPerClass));
    if (n > 0 && !std::unique_ptr<mrpt::maps::TMetricMapInitializer>(
                     mrpt::maps::TMetricMapInitializer::factory(cls)))
      throw std::runtime_error(where + ": unknown map class '" + cls + "'");
    counts[cls] = n;
  }
  for (const std::string& cls : exactly_one) {
    if (counts[cls] != 1)
      throw std::runtime_error(source + ": [" + section + "] must declare " + cls +
                               "_count = 1, got " + std::to_string(counts[cls]));
  }
  // Our maps' options, read here: through MRPT's loader an error loses its section.
  for (int k = 0; k < counts["CAppearanceMap"]; ++k)
    AppearanceMapConfig::FromConfig(ini, MapSection(section, "CAppearanceMap", k, "options"),
                                    source);
  for (int k = 0; k < counts["CDifferencingMap"]; ++k)
    DifferencingMapConfig::FromConfig(ini, MapSection(section, "CDifferencingMap", k, "options"),
                                      source);
  for (int k = 0; k < counts["CObjectDatabaseMap"]; ++k)
    ObjectDatabaseMapConfig::FromConfig(
        ini, MapSection(section, "CObjectDatabaseMap", k, "options"), source);
  for (int k = 0; k < counts["CIlluminationInvariantMap"]; ++k)
    IlluminationInvariantMapConfig::FromConfig(
        ini, MapSection(section, "CIlluminationInvariantMap", k, "options"), source);
  for (const std::string& s : sections) {
    // Only the sections named like a map's: the file may hold the program's own sections too.
    if (s.rfind(section + "_", 0) != 0) continue;
    bool read = false;
    for (const auto& [cls, n] : counts) {
      for (int k = 0; k < n && !read; ++k) {
        for (const char* part : {"options", "insertOpts", "creationOpts", "likelihoodOpts"})
          read = read || s == MapSection(section, cls, k, part);
      }
    }
    if (!read)
      throw std::runtime_error(source + ": section [" + s +
                               "] is read by no declared map (misspelt or unclosed header?)");
  }
  return counts;
}

mrpt::maps::TSetOfMetricMapInitializers LoadMultiMapConfig(
    const mrpt::config::CConfigFileBase& ini, const std::string& section, const std::string& source,
    const std::vector<std::string>& exactly_one) {
  RegisterMaps();  // for a static link; the shared library registered on load
  CheckMultiMapConfig(ini, section, source, exactly_one);
  mrpt::maps::TSetOfMetricMapInitializers inits;
  try {
    inits.loadFromConfigFile(ini, section);
  } catch (const std::exception& e) {
    throw std::runtime_error(source + ": " + sensors::BriefMessage(e));
  }
  return inits;
}

mrpt::maps::TSetOfMetricMapInitializers LoadMultiMapConfig(const std::string& path,
                                                           const std::string& section) {
  return LoadMultiMapConfig(*OpenConfigFile(path), section, path);
}

}  // namespace novelty::mrpt_plugins
