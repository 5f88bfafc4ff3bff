#include "mrpt_plugins/object_database_map_options.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

namespace novelty::mrpt_plugins {
namespace {

const std::string kThesis =
    std::string(NOVELTY_SOURCE_DIR) + "/share/thesis/object_database.ini";

// Thesis 5.1: ξ = 2, δ = 2 px, ratio 0.65, T = 0.8, active features dropped after 10 frames,
// SURF features: the thesis's file, read on top of the defaults (which are the best measured
// setting: thesis_settings_test; the shipped file their dump: appearance_map_options_test).
TEST(ObjectDatabaseMapOptions, TheThesisFileGivesTheThesisValues) {
  const auto c = ObjectDatabaseMapConfig::FromFile(kThesis, ObjectDatabaseMapConfig::kSection);
  EXPECT_EQ(c.map.extractor, objects::FeatureExtractor::kMSurf);
  EXPECT_EQ(c.map.focus.xi, 2.0);
  EXPECT_EQ(c.map.learner.static_distance_px, 2.0);
  EXPECT_EQ(c.map.learner.match_ratio, 0.65);
  EXPECT_EQ(c.map.learner.min_surprising_share, 0.8);
  EXPECT_EQ(c.map.learner.forget_after_frames, 10);
  EXPECT_TRUE(c.map.learn_unknown_change);
  EXPECT_FALSE(c.map.learner.verify_pose) << "beyond the thesis: off";
  EXPECT_FALSE(c.depth_of_room_at_start) << "beyond the thesis: off";
}

// Each switch beyond the thesis, set against its default in an .ini, reaches its own option
// and no other: a key bound to the wrong member fails here.
TEST(ObjectDatabaseMapOptions, EachSwitchReachesItsOption) {
  using Config = ObjectDatabaseMapConfig;
  const std::vector<std::pair<const char*, bool (*)(const Config&)>> switches = {
      {"learn_unknown_change", [](const Config& c) { return c.map.learn_unknown_change; }},
      {"learn_unchanged_change", [](const Config& c) { return c.map.learn_unchanged_change; }},
      {"nearer_is_surprising", [](const Config& c) { return c.map.nearer_is_surprising; }},
      {"learn_only_nearer_features",
       [](const Config& c) { return c.map.learn_only_nearer_features; }},
      {"grow_focus_over_nearer", [](const Config& c) { return c.map.grow_focus_over_nearer; }},
      {"depth_of_room_at_start", [](const Config& c) { return c.depth_of_room_at_start; }},
      {"distinct_second_match",
       [](const Config& c) { return c.map.learner.distinct_second_match; }},
      {"static_features_recognise",
       [](const Config& c) { return c.map.learner.static_features_recognise; }},
      {"verify_pose", [](const Config& c) { return c.map.learner.verify_pose; }},
  };
  const Config defaults;
  for (const auto& [key, value] : switches) {
    const bool flipped = !value(defaults);
    const Config c =
        Config::FromConfig(mrpt::config::CConfigFileMemory(std::string("[o]\n") + key + " = " +
                                                           (flipped ? "true" : "false") + "\n"),
                           "o", "test.ini");
    for (const auto& [other, other_value] : switches)
      EXPECT_EQ(other_value(c), std::string(other) == key ? flipped : other_value(defaults))
          << key << " set, " << other << " read";
  }
}

TEST(ObjectDatabaseMapOptions, BadValuesNameTheKey) {
  for (const char* line : {"extractor = surf", "match_ratio = 1.5", "forget_after_frames = 0",
                           "min_surprising_share = -0.1", "relative_descriptor_change = 0",
                           "xi = nan", "xi = -1", "verify_min_inliers = 3", "no_such_key = 1"}) {
    const std::string key = std::string(line).substr(0, std::string(line).find(' '));
    try {
      ObjectDatabaseMapConfig::FromConfig(
          mrpt::config::CConfigFileMemory(std::string("[o]\n") + line + "\n"), "o", "test.ini");
      ADD_FAILURE() << line;
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("test.ini"), std::string::npos) << what;
      EXPECT_NE(what.find(key), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace novelty::mrpt_plugins
