#include "mrpt_plugins/register_maps.h"

#include "mrpt_plugins/c_appearance_map.h"
#include "mrpt_plugins/c_differencing_map.h"

namespace novelty::mrpt_plugins {

void RegisterMaps() {
  mrpt::rtti::registerClass(CLASS_ID(CAppearanceMap));
  mrpt::rtti::registerClass(CLASS_ID(CDifferencingMap));
}

}  // namespace novelty::mrpt_plugins
