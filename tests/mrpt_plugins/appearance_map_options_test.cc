#include "mrpt_plugins/appearance_map_options.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <fstream>
#include <sstream>

#include "mrpt_plugins/differencing_map_options.h"
#include "mrpt_plugins/illumination_invariant_map_options.h"
#include "mrpt_plugins/object_database_map_options.h"

namespace novelty::mrpt_plugins {
namespace {

AppearanceMapConfig Load(const std::string& text) {
  return AppearanceMapConfig::FromConfig(mrpt::config::CConfigFileMemory(text), "AppearanceMap",
                                         "test.ini");
}

std::string ErrorOf(const std::string& text) {
  try {
    Load(text);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// The file without its leading comment lines.
std::string Body(const std::string& path) {
  std::ifstream in(path);
  std::string line, body;
  while (std::getline(in, line))
    if (!(body.empty() && line.rfind('#', 0) == 0)) body += line + "\n";
  return body;
}

TEST(AppearanceMapOptions, ShippedIniIsTheDumpOfTheDefaults) {
  std::ostringstream dump;
  AppearanceMapConfig().dumpAsMultiMap(dump);
  EXPECT_EQ(Body(std::string(NOVELTY_SOURCE_DIR) + "/share/appearance.ini"), dump.str())
      << "regenerate with: build/bin/novelty-info --dump-options CAppearanceMap";
  std::ostringstream diff_dump;
  DifferencingMapConfig().dumpAsMultiMap(diff_dump);
  EXPECT_EQ(Body(std::string(NOVELTY_SOURCE_DIR) + "/share/differencing.ini"), diff_dump.str())
      << "regenerate with: build/bin/novelty-info --dump-options CDifferencingMap";
  std::ostringstream objects_dump;
  ObjectDatabaseMapConfig().dumpAsMultiMap(objects_dump);
  EXPECT_EQ(Body(std::string(NOVELTY_SOURCE_DIR) + "/share/object_database.ini"),
            objects_dump.str())
      << "regenerate with: build/bin/novelty-info --dump-options CObjectDatabaseMap";
  std::ostringstream illumination_dump;
  IlluminationInvariantMapConfig().dumpAsMultiMap(illumination_dump);
  EXPECT_EQ(Body(std::string(NOVELTY_SOURCE_DIR) + "/share/illumination_invariant.ini"),
            illumination_dump.str())
      << "regenerate with: build/bin/novelty-info --dump-options CIlluminationInvariantMap";
}

TEST(AppearanceMapOptions, ShippedIniGivesTheThesisValues) {
  const auto c =
      AppearanceMapConfig::FromFile(std::string(NOVELTY_SOURCE_DIR) + "/share/appearance.ini");
  const auto& o = c.map;
  EXPECT_EQ(o.surprise.update.forgetting_factor, 0.8);  // thesis 4.1.2
  EXPECT_EQ(o.initial_prior.alpha, 1.0);                // thesis 4.3: α=1, β=1, τ=0, σ=5
  EXPECT_EQ(o.initial_prior.beta, 1.0);
  EXPECT_EQ(o.initial_prior.tau, 0.0);
  EXPECT_EQ(o.initial_prior.sigma, 5.0);
  EXPECT_EQ(o.surprise.update.min_variance, 1.0 / 12.0);  // the file's digits give 1/12 exactly
  EXPECT_NEAR(o.views.new_view_angle, 5.0 * M_PI / 180.0, 1e-15);
  EXPECT_EQ(o.views.blend.depth_tolerance, 0.0);  // the thesis's average
  EXPECT_EQ(o.views.blend.angle_power, 0.0);
  EXPECT_TRUE(o.views.selection.weight_by_rays);
  EXPECT_EQ(c.depth.kind, DepthSourceOptions::Kind::kRgbd);
  EXPECT_EQ(c.depth.stereo.sweep.hypotheses, 64);
}

TEST(AppearanceMapOptions, EveryFieldTheOptionsHoldCanBeSetFromTheIni) {
  const AppearanceMapConfig c = Load(
      "[AppearanceMap]\nforgetting_factor = 0.7\nhalf_precision = false\nplanar_block = 4\n"
      "planar_tolerance = 0.01\nnear_plane = 0.1\nmax_view_distance = 3\nresolution_power = 1\n");
  EXPECT_EQ(c.map.surprise.update.forgetting_factor, 0.7);
  EXPECT_FALSE(c.map.half_precision);
  EXPECT_EQ(c.map.views.warp.planar_block, 4);
  EXPECT_EQ(c.map.views.warp.planar_tolerance, 0.01);
  EXPECT_EQ(c.map.views.warp.near_plane, 0.1);
  EXPECT_EQ(c.map.views.selection.max_distance, 3.0);
  EXPECT_EQ(c.map.views.blend.resolution_power, 1.0);
}

TEST(AppearanceMapOptions, NamesBadValues) {
  EXPECT_EQ(ErrorOf("[AppearanceMap]\nforgeting_factor = 0.7\n"),
            "test.ini: [AppearanceMap] forgeting_factor: unknown option");
  EXPECT_EQ(ErrorOf("[AppearanceMap]\nxi = lots\n"),
            "test.ini: [AppearanceMap] xi = 'lots': not a number");
  EXPECT_NE(ErrorOf("[AppearanceMap]\nforgetting_factor = 1.5\n").find("forgetting_factor"),
            std::string::npos);
  for (const char* bad : {"new_view_distance = 0", "new_view_angle_deg = -1", "near_plane = 0",
                          "depth_tolerance = -0.1", "planar_block = 2.5", "initial_beta = 0"}) {
    EXPECT_NE(ErrorOf(std::string("[AppearanceMap]\n") + bad + "\n"), "") << bad;
  }
  EXPECT_EQ(ErrorOf("[AppearanceMap]\ndepth_source = lidar\n"),
            "test.ini: [AppearanceMap] depth_source = 'lidar': not rgbd or stereo");
  EXPECT_NE(ErrorOf("[AppearanceMap]\nstereo_hypotheses = 2.5\n").find("stereo_hypotheses"),
            std::string::npos);
  EXPECT_NE(ErrorOf("[AppearanceMap]\nstereo_near = 6\n").find("stereo_near"), std::string::npos);
  EXPECT_THROW(AppearanceMapConfig::FromFile("/nonexistent.ini"), std::runtime_error);
}

TEST(AppearanceMapOptions, ReadsTheDepthSource) {
  const AppearanceMapConfig c =
      Load("[AppearanceMap]\ndepth_source = stereo\nstereo_hypotheses = 32\nstereo_far = 4 ; m\n");
  EXPECT_EQ(c.depth.kind, DepthSourceOptions::Kind::kStereo);
  EXPECT_EQ(c.depth.stereo.sweep.hypotheses, 32);
  EXPECT_EQ(c.depth.stereo.sweep.far, 4.0);
  EXPECT_EQ(c.depth.stereo.sweep.near, 0.5);  // default kept
}

TEST(AppearanceMapOptions, TheDifferencingMapTakesOnlyItsOwnKeys) {
  const auto c = DifferencingMapConfig::FromConfig(
      mrpt::config::CConfigFileMemory("[d]\nnew_view_distance = 0.02\n"), "d", "d.ini");
  EXPECT_EQ(c.map.new_view_distance, 0.02);
  EXPECT_THROW(DifferencingMapConfig::FromConfig(
                   mrpt::config::CConfigFileMemory("[d]\nxi = 0.01\n"), "d", "d.ini"),
               std::runtime_error);
}

TEST(AppearanceMapOptions, TheIlluminationMapReadsTheMissingTextureAndRefusesAnEvenBlock) {
  const auto read = [](const std::string& text) {
    return IlluminationInvariantMapConfig::FromConfig(mrpt::config::CConfigFileMemory(text), "i",
                                                      "i.ini");
  };
  const auto c = read("[i]\nmissing_texture = true\ntexture_block = 9\n");
  EXPECT_TRUE(c.map.model.missing_texture);
  EXPECT_EQ(c.map.model.texture.block, 9);
  try {
    read("[i]\ntexture_block = 8\n");
    ADD_FAILURE() << "an even block was taken";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("texture_block"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace novelty::mrpt_plugins
