#include "mrpt_plugins/appearance_map_options.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

namespace novelty::mrpt_plugins {
namespace {

appearance::AppearanceMapOptions Load(const std::string& text) {
  const mrpt::config::CConfigFileMemory config(text);
  return LoadAppearanceMapOptions(config, "AppearanceMap", "test.ini");
}

std::string ErrorOf(const std::string& text) {
  try {
    Load(text);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(AppearanceMapOptions, ShippedIniGivesTheDocumentedDefaults) {
  const auto o =
      LoadAppearanceMapOptions(std::string(NOVELTY_SOURCE_DIR) + "/share/appearance.ini");
  const appearance::AppearanceMapOptions d;
  EXPECT_EQ(o.surprise.update.forgetting_factor, d.surprise.update.forgetting_factor);
  EXPECT_EQ(o.surprise.update.xi, d.surprise.update.xi);
  EXPECT_EQ(o.initial_prior.sigma, 5.0);
  EXPECT_EQ(o.half_precision, d.half_precision);
  EXPECT_NEAR(o.views.new_view_angle, d.views.new_view_angle, 1e-12);
  EXPECT_EQ(o.views.blend.depth_tolerance, 0.0);
  EXPECT_EQ(o.surprise.update.min_variance, 1.0 / 12.0);  // the file's digits give the default
  EXPECT_EQ(o.views.blend.angle_power, d.views.blend.angle_power);
  EXPECT_EQ(o.views.selection.weight_by_rays, d.views.selection.weight_by_rays);
}

TEST(AppearanceMapOptions, ReadsValuesAndNamesBadOnes) {
  const auto o = Load("[AppearanceMap]\nforgetting_factor = 0.7\nhalf_precision = false\n");
  EXPECT_EQ(o.surprise.update.forgetting_factor, 0.7);
  EXPECT_FALSE(o.half_precision);
  EXPECT_EQ(ErrorOf("[AppearanceMap]\nforgeting_factor = 0.7\n"),
            "test.ini: [AppearanceMap] forgeting_factor: unknown option");
  EXPECT_EQ(ErrorOf("[AppearanceMap]\nxi = lots\n"), "test.ini: [AppearanceMap] xi = 'lots': not a number");
  EXPECT_NE(ErrorOf("[AppearanceMap]\nforgetting_factor = 1.5\n").find("forgetting_factor"),
            std::string::npos);
  EXPECT_THROW(LoadAppearanceMapOptions("/nonexistent.ini"), std::runtime_error);
}

TEST(AppearanceMapOptions, ReadsTheDepthSource) {
  const mrpt::config::CConfigFileMemory stereo(
      "[AppearanceMap]\ndepth_source = stereo\nstereo_hypotheses = 32\nstereo_far = 4 ; m\n");
  const MapConfig c = LoadMapConfig(stereo, "AppearanceMap", "test.ini");
  EXPECT_EQ(c.depth.kind, DepthSourceOptions::Kind::kStereo);
  EXPECT_EQ(c.depth.stereo.sweep.hypotheses, 32);
  EXPECT_EQ(c.depth.stereo.sweep.far, 4.0);
  EXPECT_EQ(c.depth.stereo.sweep.near, 0.5);  // default kept
  const MapConfig shipped =
      LoadMapConfig(std::string(NOVELTY_SOURCE_DIR) + "/share/appearance.ini");
  EXPECT_EQ(shipped.depth.kind, DepthSourceOptions::Kind::kRgbd);
  EXPECT_EQ(shipped.depth.stereo.sweep.hypotheses, 64);
  EXPECT_EQ(ErrorOf("[AppearanceMap]\ndepth_source = lidar\n"),
            "test.ini: [AppearanceMap] depth_source = 'lidar': not rgbd or stereo");
  EXPECT_NE(ErrorOf("[AppearanceMap]\nstereo_hypotheses = 2.5\n").find("stereo_hypotheses"),
            std::string::npos);
  EXPECT_NE(ErrorOf("[AppearanceMap]\nstereo_near = 6\n").find("stereo_near"),
            std::string::npos);
}

}  // namespace
}  // namespace novelty::mrpt_plugins
