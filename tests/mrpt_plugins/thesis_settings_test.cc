// share/thesis/*.ini: the thesis's settings where the defaults are a better measured one. Each
// file must set exactly the keys where they differ, to the thesis's values, and nothing else.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "mrpt_plugins/illumination_invariant_map_options.h"
#include "mrpt_plugins/object_database_map_options.h"

namespace novelty::mrpt_plugins {
namespace {

std::string Thesis(const std::string& name) {
  return std::string(NOVELTY_SOURCE_DIR) + "/share/thesis/" + name;
}

// The keys whose values differ between two configurations of one table.
template <class Config>
std::set<std::string> DifferingKeys(const Config& a, const Config& b) {
  std::set<std::string> keys;
  for (const auto& row : Config::Table().rows())
    if (row.get(a) != row.get(b)) keys.insert(row.entry.key);
  return keys;
}

TEST(ThesisSettings, ObjectDatabaseDiffersFromTheDefaultsInTheNinetyPercentKeys) {
  const ObjectDatabaseMapConfig defaults;
  const ObjectDatabaseMapConfig thesis =
      ObjectDatabaseMapConfig::FromFile(Thesis("object_database.ini"));
  // docs/objects.md, "the 90 % setting": these eight keys, the rest as shipped.
  EXPECT_EQ(DifferingKeys(defaults, thesis),
            (std::set<std::string>{"extractor", "morphology_size", "learn_unchanged_change",
                                   "learn_only_nearer_features", "nearer_is_surprising",
                                   "depth_of_room_at_start", "static_features_recognise",
                                   "verify_pose"}));
  EXPECT_EQ(defaults.map.extractor, objects::FeatureExtractor::kSift);
  EXPECT_EQ(defaults.map.focus.morphology_size, 12);
  EXPECT_TRUE(defaults.map.learn_unchanged_change && defaults.map.learn_only_nearer_features &&
              defaults.map.nearer_is_surprising && defaults.depth_of_room_at_start &&
              defaults.map.learner.static_features_recognise && defaults.map.learner.verify_pose);
  // The thesis: SURF, surprise alone, no depth test, no pose verification.
  EXPECT_EQ(thesis.map.extractor, objects::FeatureExtractor::kMSurf);
  EXPECT_EQ(thesis.map.focus.morphology_size, 5);
  EXPECT_FALSE(thesis.map.learn_only_nearer_features || thesis.map.nearer_is_surprising ||
               thesis.depth_of_room_at_start || thesis.map.learner.static_features_recognise ||
               thesis.map.learner.verify_pose);
}

TEST(ThesisSettings, IlluminationInvariantMapDiffersInColourAndMissingTexture) {
  const IlluminationInvariantMapConfig defaults;
  const IlluminationInvariantMapConfig thesis =
      IlluminationInvariantMapConfig::FromFile(Thesis("illumination_invariant.ini"));
  EXPECT_EQ(DifferingKeys(defaults, thesis), (std::set<std::string>{"colour", "missing_texture"}));
  using Colour = illumination::InvariantImageOptions::Colour;
  EXPECT_EQ(defaults.map.invariant.colour, Colour::kLuminanceChromaticity);
  EXPECT_TRUE(defaults.map.model.missing_texture);
  EXPECT_EQ(thesis.map.invariant.colour, Colour::kPerChannel);
  EXPECT_FALSE(thesis.map.model.missing_texture);
  EXPECT_EQ(thesis.map.model.kappa, 0.5) << "eq. 6.18, Lambertian";
}

}  // namespace
}  // namespace novelty::mrpt_plugins
