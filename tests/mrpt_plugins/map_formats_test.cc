#include "mrpt_plugins/map_formats.h"

#include <gtest/gtest.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <set>

#include "mrpt_plugins/appearance_map_options.h"
#include "mrpt_plugins/c_appearance_map.h"
#include "mrpt_plugins/c_differencing_map.h"
#include "mrpt_plugins/c_object_database_map.h"
#include "mrpt_plugins/differencing_map_options.h"

namespace novelty::mrpt_plugins {
namespace {

// The version byte MRPT's archive writes after the class name: what a saved map says it is.
uint8_t VersionWritten(const mrpt::serialization::CSerializable& map, const std::string& name) {
  mrpt::io::CMemoryStream buffer;
  auto out = mrpt::serialization::archiveFrom(buffer);
  out << map;
  const auto* bytes = static_cast<const uint8_t*>(buffer.getRawBufferData());
  const std::size_t size = std::size_t(buffer.getTotalBytesCount());
  const auto* at = std::search(bytes, bytes + size, name.begin(), name.end());
  EXPECT_NE(at, bytes + size) << name;
  return at[name.size()];
}

TEST(MapFormats, TheClassesWriteTheCurrentVersion) {
  EXPECT_EQ(VersionWritten(CAppearanceMap(), "CAppearanceMap"), CurrentMapFormat("CAppearanceMap"));
  EXPECT_EQ(VersionWritten(CDifferencingMap(), "CDifferencingMap"),
            CurrentMapFormat("CDifferencingMap"));
  EXPECT_EQ(VersionWritten(CObjectDatabaseMap(), "CObjectDatabaseMap"),
            CurrentMapFormat("CObjectDatabaseMap"));
  // An illumination map is saved only once built (its own test checks the round trip).
  EXPECT_EQ(CurrentMapFormat("CIlluminationInvariantMap"), 2);
}

TEST(MapFormats, TheCurrentVersionIsTheFullLayout) {
  for (const char* c :
       {"CAppearanceMap", "CDifferencingMap", "CObjectDatabaseMap", "CIlluminationInvariantMap"}) {
    const MapFormat f = MapFormatOf(c, CurrentMapFormat(c)), full;
    EXPECT_TRUE(f.options_by_key) << c;
    EXPECT_TRUE(f.positional_keys.empty()) << c;
    EXPECT_FALSE(f.raw_planes) << c;
    EXPECT_EQ(f.encoding, full.encoding) << c;
    EXPECT_TRUE(f.learnt_keypoints && f.texture_tails && f.decision_threshold && f.object_info)
        << c;
  }
}

TEST(MapFormats, OlderViewMapsDifferAsDocumented) {
  // docs/map_storage.md: 0-1 positional options and raw planes, 2 options by key, 3 shuffled.
  EXPECT_FALSE(MapFormatOf("CAppearanceMap", 0).options_by_key);
  EXPECT_EQ(MapFormatOf("CAppearanceMap", 0).positional_keys.size(), 14u);
  EXPECT_EQ(MapFormatOf("CAppearanceMap", 1).positional_keys.size(), 17u);
  EXPECT_EQ(MapFormatOf("CDifferencingMap", 1).positional_keys.size(), 6u);
  for (uint8_t v : {0, 1, 2}) EXPECT_TRUE(MapFormatOf("CDifferencingMap", v).raw_planes);
  EXPECT_TRUE(MapFormatOf("CAppearanceMap", 2).options_by_key);
  EXPECT_FALSE(MapFormatOf("CAppearanceMap", 3).raw_planes);
  EXPECT_EQ(MapFormatOf("CAppearanceMap", 3).encoding, views::PlaneEncoding::kShuffled);
  EXPECT_FALSE(MapFormatOf("CObjectDatabaseMap", 0).learnt_keypoints);
  EXPECT_FALSE(MapFormatOf("CObjectDatabaseMap", 1).object_info);
  EXPECT_TRUE(MapFormatOf("CObjectDatabaseMap", 1).learnt_keypoints);
  EXPECT_FALSE(MapFormatOf("CIlluminationInvariantMap", 0).texture_tails);
  EXPECT_TRUE(MapFormatOf("CIlluminationInvariantMap", 1).texture_tails);
  EXPECT_FALSE(MapFormatOf("CIlluminationInvariantMap", 1).decision_threshold);
}

// A positional key that names no option would make an old file unreadable: each must be in the
// class's table, once.
template <class Config>
void ExpectKeysInTable(const std::string& map_class) {
  for (uint8_t v : {0, 1}) {
    const std::vector<std::string> keys = MapFormatOf(map_class, v).positional_keys;
    EXPECT_EQ(std::set<std::string>(keys.begin(), keys.end()).size(), keys.size()) << map_class;
    for (const std::string& key : keys) {
      const auto& rows = Config::Table().rows();
      EXPECT_TRUE(
          std::any_of(rows.begin(), rows.end(), [&](const auto& r) { return r.entry.key == key; }))
          << map_class << " version " << int(v) << ": " << key;
    }
  }
}

TEST(MapFormats, PositionalKeysAreOptionsOfTheirClass) {
  ExpectKeysInTable<AppearanceMapConfig>("CAppearanceMap");
  ExpectKeysInTable<DifferencingMapConfig>("CDifferencingMap");
}

TEST(MapFormats, ANewerVersionIsAnErrorNamingBoth) {
  try {
    MapFormatOf("CObjectDatabaseMap", 7);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "map file: format version 7, newer than this program's (2)");
  }
  EXPECT_THROW(MapFormatOf("COccupancyGridMap2D", 0), std::logic_error);
}

}  // namespace
}  // namespace novelty::mrpt_plugins
