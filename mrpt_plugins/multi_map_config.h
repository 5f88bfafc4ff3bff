// Checks of a CMultiMetricMap .ini that MRPT's loader (TSetOfMetricMapInitializers::
// loadFromConfigFile) does not make: it passes over keys that are no <Class>_count, classes it
// does not know and sections no map reads (a misspelt or unclosed header), so a mistyped option
// would silently fall back to its default. Each is an error here, naming the file and section.
#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <map>
#include <string>
#include <vector>

namespace novelty::mrpt_plugins {

/// Checks `section` (e.g. "map") of `ini` and returns the declared count per map class. Only
/// <Class>_count keys of registered classes (RegisterMaps() for ours) are allowed there; every
/// other section must be one a declared map reads (<section>_<Class>_<NN>_options, …_insertOpts,
/// …_creationOpts, …_likelihoodOpts); our maps' option sections are read (unknown keys and bad
/// values are errors); the classes in `exactly_one` must be declared once each. Throws
/// std::runtime_error naming `source`.
std::map<std::string, int> CheckMultiMapConfig(const mrpt::config::CConfigFileBase& ini,
                                               const std::string& section,
                                               const std::string& source,
                                               const std::vector<std::string>& exactly_one = {});

}  // namespace novelty::mrpt_plugins
