#include "experiments/maps_config.h"

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <mrpt/maps/CMultiMetricMap.h>
#include "mrpt_plugins/multi_map_config.h"

namespace novelty::experiments {
namespace {

std::vector<std::string> Classes(const mrpt::maps::TSetOfMetricMapInitializers& inits) {
  mrpt::maps::CMultiMetricMap maps;
  maps.setListOfMaps(inits);
  std::vector<std::string> names;
  for (const auto& m : maps.maps) names.push_back(m->GetRuntimeClass()->className);
  return names;
}

// The maps an experiment plays into without an .ini are those share/novelty_run.ini declares,
// each at its defaults: what the README tells a user to copy is what runs without it.
TEST(MapsConfig, TheDefaultMapsAreShareNoveltyRunIni) {
  const MapsConfig defaults = OpenMapsConfig("");
  EXPECT_EQ(defaults.source, "the default maps");
  const MapsConfig shipped =
      OpenMapsConfig(std::string(NOVELTY_SOURCE_DIR) + "/share/novelty_run.ini");
  const auto a = mrpt_plugins::LoadMultiMapConfig(*defaults.ini, "map", defaults.source);
  const auto b = mrpt_plugins::LoadMultiMapConfig(*shipped.ini, "map", shipped.source);
  EXPECT_EQ(Classes(a), Classes(b));
  EXPECT_EQ(Classes(a).size(), 2u);
  // Every option at its default in both: the definitions dump the same text.
  std::ostringstream da, db;
  a.dumpToTextStream(da);
  b.dumpToTextStream(db);
  EXPECT_EQ(da.str(), db.str());
}

TEST(MapsConfig, AFileThatIsNotThereIsNamed) {
  try {
    OpenMapsConfig("/nonexistent/maps.ini");
    ADD_FAILURE();
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/maps.ini"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace novelty::experiments
