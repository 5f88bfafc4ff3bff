// Makes NoveltyMaps' map classes known to MRPT: to its class registry (reading archives) and to
// the CMultiMetricMap .ini factory ("CAppearanceMap", "CDifferencingMap"). A program that uses
// the classes only by name — from an .ini file or an archive — calls this once before, like
// MRPT's own registerAllClasses_*() functions; referencing the classes here also keeps a static
// link from dropping their registration code.
#pragma once

namespace novelty::mrpt_plugins {

void RegisterMaps();

}  // namespace novelty::mrpt_plugins
