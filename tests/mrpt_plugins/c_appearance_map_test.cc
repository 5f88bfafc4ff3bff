#include "mrpt_plugins/c_appearance_map.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfObjects.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "mrpt_plugins/map_file.h"
#include "mrpt_plugins/view_archive.h"
#include "tests/mrpt_plugins/clip_observations.h"

namespace novelty::mrpt_plugins {
namespace {

namespace fs = std::filesystem;

// The relative L1 difference of two maps' surprise over the frames added, which must cover the
// same pixels (the 1 % target of the reliability issue is on this).
struct SurpriseDifference {
  double error = 0.0, total = 0.0;
  // Adds one frame's surprise images; false (and a test failure) if coverage differs.
  bool Add(const cv::Mat& a, const cv::Mat& b, std::size_t frame) {
    for (int i = 0; i < int(a.total()); ++i) {
      const float x = a.at<float>(i), y = b.at<float>(i);
      if (std::isnan(x) != std::isnan(y)) {
        ADD_FAILURE() << "frame " << frame << ": coverage differs at pixel " << i;
        return false;
      }
      if (std::isnan(x)) continue;
      error += std::abs(x - y);
      total += std::abs(x);
    }
    return true;
  }
  double Relative() const { return error / total; }
};

// Map files store the planes compactly (views::EncodePlane): the surprise a reloaded map gives is
// within 1 % (relative L1, the reliability issue's target) of the map's that was never saved,
// over the same pixels.
TEST(CAppearanceMap, SurpriseAfterACompactSaveAndLoadIsWithinOnePercentOfWithout) {
  CAppearanceMap kept;
  for (int k = 0; k < 20; ++k) ASSERT_TRUE(kept.insertObservation(Observation(Frames()[k])));
  EXPECT_FALSE(kept.isEmpty());
  const fs::path file = fs::temp_directory_path() / "novelty_test.appearance_map";
  kept.SaveToFile(file.string());
  CAppearanceMap reloaded;
  reloaded.LoadFromFile(file.string());
  EXPECT_EQ(reloaded.map().store().size(), kept.map().store().size());
  SurpriseDifference d;
  for (std::size_t k = 20; k < Frames().size(); ++k) {
    kept.insertObservation(Observation(Frames()[k]));
    reloaded.insertObservation(Observation(Frames()[k]));
    ASSERT_TRUE(d.Add(kept.lastProducts().surprise, reloaded.lastProducts().surprise, k));
  }
  ASSERT_GT(d.total, 0.0);
  EXPECT_LT(d.Relative(), 0.01);
  std::printf("[ COMPACT  ] surprise after reload: relative L1 error %.4f %%\n",
              100 * d.Relative());
}

// A map that holds its views compact in memory (all but the last `decoded_views`, rounded and
// predicted: plane_codec.h) gives the surprise of one that holds them all decoded within 1 %
// (relative L1, the reliability issue's target) over the same pixels, and its compact views
// take at most 8.47 bytes a pixel: with the default 12 decoded views (30 B/pixel each), 200
// views at 320×240 then fit the issue's 150 MB.
TEST(CAppearanceMap, ACompactMapInMemoryGivesTheSurpriseOfADecodedOneWithinOnePercent) {
  AppearanceMapConfig decoded_config, compact_config;
  decoded_config.map.views.storage.decoded_views = 0;
  compact_config.map.views.storage.decoded_views = 2;  // evictions at almost every frame
  CAppearanceMap decoded(decoded_config), compact(compact_config);
  SurpriseDifference d;
  // Twice through the clip: the second pass predicts from views evicted long before.
  for (std::size_t n = 0; n < 2 * Frames().size(); ++n) {
    const std::size_t k = n % Frames().size();
    ASSERT_TRUE(decoded.insertObservation(Observation(Frames()[k])));
    ASSERT_TRUE(compact.insertObservation(Observation(Frames()[k])));
    ASSERT_TRUE(d.Add(decoded.lastProducts().surprise, compact.lastProducts().surprise, n));
  }
  ASSERT_GT(d.total, 0.0);
  EXPECT_LT(d.Relative(), 0.01);
  EXPECT_GT(compact.map().store().counts().decoded, 0) << "no compact view was used again";
  const views::ReferenceViewStore& store = compact.map().store();
  ASSERT_EQ(store.size(), decoded.map().store().size());
  int decoded_views = 0;
  std::size_t compact_bytes = 0;
  for (int j = 0; j < store.size(); ++j) {
    if (store.decoded(j))
      ++decoded_views;
    else
      compact_bytes += store.Encoded(j).BytesUsed();
  }
  EXPECT_EQ(decoded_views, 2);
  const double pixels = double(store.camera(0).width) * store.camera(0).height;
  const double per_pixel = compact_bytes / pixels / (store.size() - decoded_views);
  EXPECT_LE(per_pixel, 8.47);
  std::printf(
      "[ COMPACT  ] in memory: %d views, %.2f B/pixel compact (%.1f decoded), "
      "surprise relative L1 error %.2g %%\n",
      store.size(), per_pixel, double(decoded.map().store().BytesUsed()) / pixels / store.size(),
      100 * d.Relative());
}

// Reads map-file bodies of any version, as MRPT's archive does after the class name.
struct FileReader : CAppearanceMap {
  using CAppearanceMap::CAppearanceMap;
  using CAppearanceMap::serializeFrom;
  using CAppearanceMap::serializeTo;
};

// The options of a map file body written as versions 0 and 1 did: values one after another
// (flags as bools, the view angle in radians), then the views.
void WriteOldOptions(mrpt::serialization::CArchive& out, int version) {
  out << 0.7 << 0.02 << 0.01 << 5.0   // forgetting_factor, xi, sigma_min, sigma_max
      << 1.0 << 1.0 << 0.0 << 5.0     // initial prior
      << false << true                // fast_approximations, half_precision
      << 0.01 << 0.1 << 0.05 << 0.0;  // new_view_distance, new_view_angle (rad), jump, tolerance
  if (version >= 1) out << 0.05 << 2.0 << true;  // min_variance, angle_power, weight_by_rays
}

TEST(CAppearanceMap, MapFilesOfEveryVersionLoadWithTheOptionsTheyWereMadeWith) {
  CAppearanceMap source;
  for (int k = 0; k < 5; ++k) ASSERT_TRUE(source.insertObservation(Observation(Frames()[k])));
  for (const int version : {0, 1}) {
    mrpt::io::CMemoryStream buffer;
    auto out = mrpt::serialization::archiveFrom(buffer);
    WriteOldOptions(out, version);
    WriteViewMap(out, source.map().view_map(),
                 MapFormatOf("CAppearanceMap", uint8_t(version)));  // raw images, as then
    buffer.Seek(0);
    auto in = mrpt::serialization::archiveFrom(buffer);
    FileReader loaded;
    loaded.serializeFrom(in, uint8_t(version));
    const appearance::AppearanceMapOptions& o = loaded.map().options();
    EXPECT_EQ(o.surprise.update.forgetting_factor, 0.7) << version;
    EXPECT_EQ(o.surprise.update.xi, 0.02);
    EXPECT_EQ(o.views.new_view_distance, 0.01);
    EXPECT_EQ(o.views.new_view_angle, 0.1);
    EXPECT_EQ(loaded.map().store().size(), source.map().store().size());
    // Version 0 predates these options: the behaviour it had (no variance floor, the plain
    // average of distinct views).
    EXPECT_EQ(o.surprise.update.min_variance, version == 0 ? 0.0 : 0.05);
    EXPECT_EQ(o.views.blend.angle_power, version == 0 ? 0.0 : 2.0);
    EXPECT_EQ(o.views.selection.weight_by_rays, version == 1);
    // Options no older file held keep their defaults.
    EXPECT_EQ(o.views.warp.planar_block, appearance::ViewBasedMapOptions().warp.planar_block);
  }
  // Versions 2-4: every option by key, the depth source too; then the views raw (2), encoded
  // without (3) or with prediction (4, what a compact map holds).
  AppearanceMapConfig c;
  c.map.views.warp.planar_block = 4;
  c.map.surprise.update.xi = 0.03;
  c.depth.kind = DepthSourceOptions::Kind::kStereo;
  for (const int version : {2, 3, 4}) {
    mrpt::io::CMemoryStream buffer;
    auto out = mrpt::serialization::archiveFrom(buffer);
    AppearanceMapConfig::Table().Write(out, c);
    WriteViewMap(out, source.map().view_map(), MapFormatOf("CAppearanceMap", uint8_t(version)));
    buffer.Seek(0);
    auto in = mrpt::serialization::archiveFrom(buffer);
    FileReader loaded;
    loaded.serializeFrom(in, uint8_t(version));
    EXPECT_EQ(loaded.map().options().views.warp.planar_block, 4) << version;
    EXPECT_EQ(loaded.map().options().surprise.update.xi, 0.03);
    EXPECT_EQ(loaded.depthSource().kind, DepthSourceOptions::Kind::kStereo);
    ASSERT_EQ(loaded.map().store().size(), source.map().store().size());
    // Raw images come back exactly; encoded ones rounded (plane_codec.h: τ within 2⁻¹⁵).
    const cv::Mat a = source.map().store().Decoded(0).planes.at("tau"),
                  b = loaded.map().store().Decoded(0).planes.at("tau");
    EXPECT_LE(cv::norm(a, b, cv::NORM_INF), version == 2 ? 0.0 : 255.0 / 32768) << version;
  }
  mrpt::io::CMemoryStream buffer;
  auto out = mrpt::serialization::archiveFrom(buffer);
  FileReader(c).serializeTo(out);
  buffer.Seek(0);
  auto again = mrpt::serialization::archiveFrom(buffer);
  try {  // a newer file than this build reads
    FileReader().serializeFrom(again, 5);
    ADD_FAILURE() << "version 5 was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("format version 5, newer than this program's (4)"),
              std::string::npos)
        << e.what();
  }
}

// A map file from a newer build: an option this build does not know.
struct NewerWriter : CAppearanceMap {
  void serializeTo(mrpt::serialization::CArchive& out) const override {
    out << uint32_t(1) << std::string("option_of_the_future") << 1.0;
  }
};

TEST(CAppearanceMap, SavedFilesKeepTheDepthSourceAndSayWhatTheyCannotRead) {
  AppearanceMapConfig c;
  c.depth.kind = DepthSourceOptions::Kind::kStereo;
  c.depth.stereo.sweep.hypotheses = 32;
  CAppearanceMap stereo(c);
  for (int k = 0; k < 3; ++k) ASSERT_TRUE(stereo.insertObservation(Observation(Frames()[k])));
  const fs::path file = fs::temp_directory_path() / "novelty_test_stereo.appearance_map";
  stereo.SaveToFile(file.string());
  CAppearanceMap loaded;
  loaded.LoadFromFile(file.string());
  EXPECT_EQ(loaded.depthSource().kind, DepthSourceOptions::Kind::kStereo);
  EXPECT_EQ(loaded.depthSource().stereo.sweep.hypotheses, 32);

  SaveAtomically(NewerWriter(), file.string());
  try {
    loaded.LoadFromFile(file.string());
    FAIL() << "a file with an unknown option loaded";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(
        std::string(e.what()),
        file.string() + ": unknown option 'option_of_the_future' (written by a newer version?)");
  }
  EXPECT_EQ(loaded.map().store().size(), stereo.map().store().size());  // kept
  fs::remove(file);
}

TEST(CAppearanceMap, TruncatedOrForeignFilesAreRejectedAndTheMapKept) {
  CAppearanceMap map;
  for (int k = 0; k < 5; ++k) map.insertObservation(Observation(Frames()[k]));
  const fs::path file = fs::temp_directory_path() / "novelty_truncated.appearance_map";
  map.SaveToFile(file.string());
  fs::resize_file(file, fs::file_size(file) / 2);
  CAppearanceMap other;
  for (int k = 0; k < 3; ++k) other.insertObservation(Observation(Frames()[k]));
  const int before = other.map().store().size();
  EXPECT_THROW(other.LoadFromFile(file.string()), std::runtime_error);
  std::ofstream(file, std::ios::trunc) << "not a map at all";
  try {
    other.LoadFromFile(file.string());
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(other.map().store().size(), before);
  other.insertObservation(Observation(Frames()[3]));  // and it still works
}

// A save that cannot be written says so in one line naming the file, and leaves nothing behind.
TEST(CAppearanceMap, AnUnwritableSaveIsOneLineNamingTheFile) {
  CAppearanceMap map;
  map.insertObservation(Observation(Frames()[0]));
  // A missing folder (nothing can be written), and a path that is a folder (the temporary file
  // is written, the rename fails).
  const fs::path busy = fs::temp_directory_path() / "novelty_save_onto_a_folder";
  fs::create_directories(busy / "inside");
  for (const fs::path& file :
       {fs::temp_directory_path() / "novelty_no_such_folder" / "map.bin", busy}) {
    try {
      map.SaveToFile(file.string());
      ADD_FAILURE() << file;
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(file.string() + ": cannot save", 0), 0u) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
    EXPECT_FALSE(fs::exists(file.string() + ".tmp")) << file;
  }
  EXPECT_TRUE(fs::is_directory(busy / "inside"));  // untouched
  fs::remove_all(busy);
}

TEST(CAppearanceMap, DeclaredInAMultiMetricMapIniWithItsOptions) {
  const mrpt::config::CConfigFileMemory ini(R"(
[map]
CAppearanceMap_count = 1
[map_CAppearanceMap_00_options]
forgetting_factor = 0.7
)");
  mrpt::maps::TSetOfMetricMapInitializers inits;
  inits.loadFromConfigFile(ini, "map");
  mrpt::maps::CMultiMetricMap multi;
  multi.setListOfMaps(inits);
  ASSERT_EQ(multi.maps.size(), 1u);
  const auto map = std::dynamic_pointer_cast<CAppearanceMap>(multi.maps[0]);
  ASSERT_TRUE(map);
  EXPECT_EQ(map->map().options().surprise.update.forgetting_factor, 0.7);
}

TEST(CAppearanceMap, VisualisationHasOneFrustumPerView) {
  CAppearanceMap map;
  for (int k = 0; k < 6; ++k) map.insertObservation(Observation(Frames()[k]));
  mrpt::opengl::CSetOfObjects objects;
  map.getVisualizationInto(objects);
  EXPECT_EQ(int(objects.size()), map.map().store().size());
  EXPECT_NE(map.asString().find("reference views"), std::string::npos);
  // The scene file MRPT's SceneViewer3D opens reads back with the same objects.
  const fs::path scene_file = fs::temp_directory_path() / "novelty_test_map.3Dscene";
  map.SaveSceneFile(scene_file.string());
  mrpt::opengl::COpenGLScene scene;
  ASSERT_TRUE(scene.loadFromFile(scene_file.string()));
  const auto loaded = scene.getByClass<mrpt::opengl::CSetOfObjects>();
  ASSERT_TRUE(loaded);
  EXPECT_EQ(int(loaded->size()), map.map().store().size());
}

}  // namespace
}  // namespace novelty::mrpt_plugins
