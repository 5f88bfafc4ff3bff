#include "mrpt_plugins/multi_map_config.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <stdexcept>

#include "mrpt_plugins/register_maps.h"

namespace novelty::mrpt_plugins {
namespace {

// The error CheckMultiMapConfig gives for `text`, or "" when it accepts it.
std::string ErrorOf(const std::string& text) {
  RegisterMaps();
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
}

}  // namespace
}  // namespace novelty::mrpt_plugins
