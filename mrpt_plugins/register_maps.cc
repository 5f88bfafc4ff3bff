#include "mrpt_plugins/register_maps.h"

#include <mrpt/core/initializer.h>

#include "mrpt_plugins/c_appearance_map.h"
#include "mrpt_plugins/c_differencing_map.h"
#include "mrpt_plugins/c_illumination_invariant_map.h"
#include "mrpt_plugins/c_object_database_map.h"

namespace novelty::mrpt_plugins {

void RegisterMaps() {
  mrpt::rtti::registerClass(CLASS_ID(CAppearanceMap));
  mrpt::rtti::registerClass(CLASS_ID(CDifferencingMap));
  mrpt::rtti::registerClass(CLASS_ID(CObjectDatabaseMap));
  mrpt::rtti::registerClass(CLASS_ID(CIlluminationInvariantMap));
}

}  // namespace novelty::mrpt_plugins

// On load of the library (a constructor function); the .ini factory entries register themselves
// through MAP_DEFINITION_REGISTER's static initialisers in the map classes' files.
MRPT_INITIALIZER(RegisterNoveltyMapsOnLoad) {
  novelty::mrpt_plugins::RegisterMaps();
}
