// Checks of a CMultiMetricMap .ini that MRPT's loader (TSetOfMetricMapInitializers::
// loadFromConfigFile) does not make: it passes over keys that are no <Class>_count, classes it
// does not know and sections no map reads (a misspelt or unclosed header), so a mistyped option
// would silently fall back to its default. Each is an error here, naming the file and section.
#pragma once

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/maps/TMetricMapInitializer.h>

#include <map>
#include <string>
#include <vector>

namespace novelty::mrpt_plugins {

/// Checks `section` (e.g. "map") of `ini` and returns the declared count per map class. Only
/// <Class>_count keys of registered classes (RegisterMaps() for ours) are allowed there; every
/// section named "<section>_…" must be one a declared map reads (<section>_<Class>_<NN>_options,
/// …_insertOpts, …_creationOpts, …_likelihoodOpts); our maps' option sections are read (unknown
/// keys and bad values are errors); the classes in `exactly_one` must be declared once each. Throws
/// std::runtime_error naming `source`.
std::map<std::string, int> CheckMultiMapConfig(const mrpt::config::CConfigFileBase& ini,
                                               const std::string& section,
                                               const std::string& source,
                                               const std::vector<std::string>& exactly_one = {});

/// The maps declared in `section` of `ini`, checked by CheckMultiMapConfig, then read by MRPT's
/// loader: the list for CMultiMetricMap::setListOfMaps. Every error names `source`.
mrpt::maps::TSetOfMetricMapInitializers LoadMultiMapConfig(
    const mrpt::config::CConfigFileBase& ini, const std::string& section, const std::string& source,
    const std::vector<std::string>& exactly_one = {});

/// The same for the .ini file `path` (a missing or unparsable file is an error naming it).
mrpt::maps::TSetOfMetricMapInitializers LoadMultiMapConfig(const std::string& path,
                                                           const std::string& section = "map");

}  // namespace novelty::mrpt_plugins
