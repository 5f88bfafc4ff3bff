// The maps are known to MRPT once the library is loaded, before (and without) RegisterMaps():
// this test binary never calls it.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/rtti/CObject.h>

#include "mrpt_plugins/c_appearance_map.h"

namespace novelty::mrpt_plugins {
namespace {

TEST(RegisterMaps, HappensWhenTheLibraryLoads) {
  // The class registry (reading archives) ...
  EXPECT_NE(mrpt::rtti::findRegisteredClass("CAppearanceMap"), nullptr);
  EXPECT_NE(mrpt::rtti::findRegisteredClass("CDifferencingMap"), nullptr);
  // ... and MRPT's own .ini loader, with no help from ours.
  mrpt::maps::TSetOfMetricMapInitializers inits;
  inits.loadFromConfigFile(mrpt::config::CConfigFileMemory(
                               "[map]\nCAppearanceMap_count = 1\nCDifferencingMap_count = 1\n"),
                           "map");
  mrpt::maps::CMultiMetricMap maps;
  maps.setListOfMaps(inits);
  EXPECT_EQ(maps.maps.size(), 2u);
  EXPECT_TRUE(maps.mapByClass<CAppearanceMap>());
}

}  // namespace
}  // namespace novelty::mrpt_plugins
