#include "mrpt_plugins/c_differencing_map.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>

#include <filesystem>

#include "tests/mrpt_plugins/clip_observations.h"

namespace novelty::mrpt_plugins {
namespace {

namespace fs = std::filesystem;

// As CAppearanceMap's: the difference after a compact save and load within 1 % (relative L1).
TEST(CDifferencingMap, DifferenceAfterACompactSaveAndLoadIsWithinOnePercentOfWithout) {
  CDifferencingMap kept;
  for (int k = 0; k < 20; ++k) ASSERT_TRUE(kept.insertObservation(Observation(Frames()[k])));
  const fs::path file = fs::temp_directory_path() / "novelty_test.differencing_map";
  kept.SaveToFile(file.string());
  CDifferencingMap reloaded;
  reloaded.LoadFromFile(file.string());
  double error = 0.0, total = 0.0;
  for (std::size_t k = 20; k < Frames().size(); ++k) {
    kept.insertObservation(Observation(Frames()[k]));
    reloaded.insertObservation(Observation(Frames()[k]));
    const cv::Mat a = kept.lastProducts().difference, b = reloaded.lastProducts().difference;
    for (int i = 0; i < a.rows * a.cols; ++i) {
      const float x = a.at<float>(i), y = b.at<float>(i);
      ASSERT_EQ(std::isnan(x), std::isnan(y)) << "frame " << k << " pixel " << i;
      if (std::isnan(x)) continue;
      error += std::abs(x - y);
      total += std::abs(x);
    }
  }
  ASSERT_GT(total, 0.0);
  EXPECT_LT(error / total, 0.01);
  EXPECT_GT(cv::countNonZero(kept.lastProducts().valid), 1000);
}

TEST(CDifferencingMap, DeclaredBesideTheAppearanceMapInOneIni) {
  const mrpt::config::CConfigFileMemory ini(R"(
[map]
CAppearanceMap_count = 1
CDifferencingMap_count = 1
[map_CDifferencingMap_00_options]
new_view_distance = 0.02
)");
  mrpt::maps::TSetOfMetricMapInitializers inits;
  inits.loadFromConfigFile(ini, "map");
  mrpt::maps::CMultiMetricMap multi;
  multi.setListOfMaps(inits);
  ASSERT_EQ(multi.maps.size(), 2u);
  const auto diff = multi.mapByClass<CDifferencingMap>();
  ASSERT_TRUE(diff);
  EXPECT_EQ(diff->map().options().new_view_distance, 0.02);
  // Both maps take the same observation through the multi-map.
  EXPECT_TRUE(multi.insertObservation(Observation(Frames()[0])));
  EXPECT_FALSE(diff->isEmpty());
}

}  // namespace
}  // namespace novelty::mrpt_plugins
