// Makes NoveltyMaps' map classes known to MRPT: to its class registry (reading archives) and to
// the CMultiMetricMap .ini factory ("CAppearanceMap", "CDifferencingMap"). This happens when the
// library is loaded, as MRPT's own modules register theirs, so a program that names the maps only
// in an .ini file or an archive finds them. RegisterMaps() does it again (harmless); a program
// linked statically calls it once, which also keeps the linker from dropping the classes.
#pragma once

namespace novelty::mrpt_plugins {

void RegisterMaps();

}  // namespace novelty::mrpt_plugins
