#include "mrpt_plugins/multi_map_config.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "mrpt_plugins/c_appearance_map.h"
#include "mrpt_plugins/c_differencing_map.h"
#include "mrpt_plugins/c_object_database_map.h"

namespace novelty::mrpt_plugins {
namespace {

// The error CheckMultiMapConfig gives for `text`, or "" when it accepts it.
std::string ErrorOf(const std::string& text) {
  const mrpt::config::CConfigFileMemory ini(text);
  try {
    CheckMultiMapConfig(ini, "map", "maps.ini", {"CAppearanceMap"});
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(CheckMultiMapConfig, AcceptsADeclarationWithItsOptions) {
  EXPECT_EQ(ErrorOf("[map]\nCAppearanceMap_count = 1\nCDifferencingMap_count = 1\n"
                    "[map_CAppearanceMap_00_options]\nxi = 0.02\n"
                    "[map_CDifferencingMap_00_options]\n"),
            "");
}

// What MRPT's own loader passes over in silence, each an error naming file and section.
TEST(CheckMultiMapConfig, RejectsWhatMrptsLoaderIgnores) {
  EXPECT_EQ(ErrorOf("[map]\nCAppearanceMap_count = 1\nCFooMap_count = 1\n"),
            "maps.ini: [map] CFooMap_count: unknown map class 'CFooMap'");
  EXPECT_EQ(ErrorOf("[map]\nCAppearanceMap_count = 1\n[map_CAppearanceMap_0_options]\nxi = 1\n"),
            "maps.ini: section [map_CAppearanceMap_0_options] is read by no declared map "
            "(misspelt or unclosed header?)");
  EXPECT_EQ(ErrorOf("[map]\nCAppearanceMap_count = 1\n[map_CAppearanceMap_00_options]\n"
                    "forgeting_factor = 0.7\n"),
            "maps.ini: [map_CAppearanceMap_00_options] forgeting_factor: unknown option");
  EXPECT_EQ(ErrorOf("[map]\nCAppearanceMap_count = 1\n[map_CAppearanceMap_00_options]\n"
                    "xi = abc\n"),
            "maps.ini: [map_CAppearanceMap_00_options] xi = 'abc': not a number");
  EXPECT_EQ(ErrorOf("[map]\nCAppearanceMap_count = 2\n"),
            "maps.ini: [map] must declare CAppearanceMap_count = 1, got 2");
  EXPECT_EQ(ErrorOf("[map]\nCAppearanceMap_count = 1\nxi = 0.1\n"),
            "maps.ini: [map] xi: only <MapClass>_count keys belong in [map]");
  EXPECT_NE(ErrorOf("[map]\nCAppearanceMap_count = 1\n[map_CAppearanceMap_00_options\nxi = 9\n"),
            "");  // an unclosed header
  EXPECT_EQ(ErrorOf("[maps]\nCAppearanceMap_count = 1\n"),
            "maps.ini: no section [map] declaring maps (<MapClass>_count = N)");
  EXPECT_EQ(ErrorOf("[map]\nCAppearanceMap_count = one\n"),
            "maps.ini: [map] CAppearanceMap_count = 'one': not a count in 0…16");
  EXPECT_EQ(ErrorOf("[map]\nCAppearanceMap_count = 1000000\n"),
            "maps.ini: [map] CAppearanceMap_count = '1000000': not a count in 0…16");
  EXPECT_EQ(ErrorOf("[map]\nCAppearanceMap_count = 1 ; the map\n"), "");
  // The program's own sections may share the file; only map-like names are checked.
  EXPECT_EQ(ErrorOf("[SLAM]\nrate = 5\n[map]\nCAppearanceMap_count = 1\n"), "");
}

std::string Read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string Shipped(const char* name) {
  return Read(std::string(NOVELTY_SOURCE_DIR) + "/share/" + name);
}

// share/appearance.ini and share/differencing.ini drop into a CMultiMetricMap file as they are:
// each alone declares its map, and the two pasted one after the other declare both (MRPT merges
// the repeated [map] section).
TEST(LoadMultiMapConfig, TheShippedFilesDropIn) {
  for (const char* name : {"appearance.ini", "differencing.ini", "object_database.ini"}) {
    const auto inits =
        LoadMultiMapConfig(mrpt::config::CConfigFileMemory(Shipped(name)), "map", name);
    EXPECT_EQ(inits.size(), 1u) << name;
  }
  const std::string both = Shipped("appearance.ini") + Shipped("differencing.ini");
  mrpt::maps::CMultiMetricMap maps;
  maps.setListOfMaps(LoadMultiMapConfig(mrpt::config::CConfigFileMemory(both), "map", "both"));
  ASSERT_EQ(maps.maps.size(), 2u);
  EXPECT_TRUE(maps.mapByClass<CAppearanceMap>());
  EXPECT_TRUE(maps.mapByClass<CDifferencingMap>());
  // The object database after the appearance map, linked to it.
  const std::string objects = Shipped("appearance.ini") + Shipped("object_database.ini");
  mrpt::maps::CMultiMetricMap with_objects;
  with_objects.setListOfMaps(
      LoadMultiMapConfig(mrpt::config::CConfigFileMemory(objects), "map", "objects"));
  ASSERT_EQ(with_objects.maps.size(), 2u);
  EXPECT_NO_THROW(LinkObjectDatabaseMaps(with_objects));
}

// A typo in a pasted file: the error names the file, the section and the key.
TEST(LoadMultiMapConfig, TyposNameFileSectionAndKey) {
  std::string text = Shipped("appearance.ini");
  const auto at = text.find("forgetting_factor");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 17, "forgeting_factor");
  try {
    LoadMultiMapConfig(mrpt::config::CConfigFileMemory(text), "map", "robot.ini");
    ADD_FAILURE() << "a misspelt key was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "robot.ini: [map_CAppearanceMap_00_options] forgeting_factor: unknown option");
  }
  std::string count = Shipped("appearance.ini");
  count.replace(count.find("CAppearanceMap_count"), 20, "CApearanceMap_count");
  EXPECT_THROW(LoadMultiMapConfig(mrpt::config::CConfigFileMemory(count), "map", "robot.ini"),
               std::runtime_error);
  EXPECT_THROW(LoadMultiMapConfig("/nonexistent/robot.ini"), std::runtime_error);
}

}  // namespace
}  // namespace novelty::mrpt_plugins
