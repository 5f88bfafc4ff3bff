#include "mrpt_plugins/map_file.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <thread>
#include <vector>

#include "mrpt_plugins/c_appearance_map.h"
#include "mrpt_plugins/c_object_database_map.h"
#include "tests/mrpt_plugins/clip_observations.h"

namespace novelty::mrpt_plugins {
namespace {

namespace fs = std::filesystem;

std::vector<char> FileBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A process saving two maps in turn onto one file is killed (SIGKILL) at random moments: the file
// on disk is always exactly one of the two maps, and loads.
TEST(SaveAtomically, AProcessKilledWhileSavingLeavesTheOldMapOrTheNew) {
  CAppearanceMap a, b;
  for (int k = 0; k < 2; ++k) a.insertObservation(Observation(Frames()[k]));
  for (int k = 0; k < 6; ++k) b.insertObservation(Observation(Frames()[k]));
  const fs::path dir = fs::temp_directory_path() / "novelty_sigkill";
  fs::create_directories(dir);
  const fs::path file = dir / "map.appearance_map";
  a.SaveToFile((dir / "a").string());
  b.SaveToFile((dir / "b").string());
  const std::vector<char> bytes_a = FileBytes(dir / "a"), bytes_b = FileBytes(dir / "b");
  ASSERT_NE(bytes_a, bytes_b);
  std::mt19937 random(7);
  int saw_a = 0, saw_b = 0;
  constexpr int kKills = 40;
  for (int kill = 0; kill < kKills; ++kill) {
    a.SaveToFile(file.string());
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {  // saves b, a, b, … until killed
      for (int i = 0;; ++i) (i % 2 ? a : b).SaveToFile(file.string());
    }
    // Saves take a few milliseconds: moments spread over several of them.
    std::this_thread::sleep_for(
        std::chrono::microseconds(std::uniform_int_distribution<int>(0, 300000)(random)));
    ::kill(child, SIGKILL);
    int status = 0;
    waitpid(child, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the saving process ended by itself";
    const std::vector<char> on_disk = FileBytes(file);
    const bool is_a = on_disk == bytes_a, is_b = on_disk == bytes_b;
    EXPECT_TRUE(is_a || is_b) << "kill " << kill << ": " << on_disk.size() << " bytes, neither map";
    saw_a += is_a;
    saw_b += is_b;
    CAppearanceMap loaded;
    EXPECT_NO_THROW(loaded.LoadFromFile(file.string())) << "kill " << kill;
  }
  EXPECT_GT(saw_b, 0) << "no kill came after a save finished: the test proves nothing";
  std::printf("[ SIGKILL  ] %d kills: %d left the first map, %d the second\n", kKills, saw_a,
              saw_b);
  fs::remove_all(dir);
}

void WriteBytes(const fs::path& p, const std::vector<char>& bytes) {
  std::ofstream(p, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

// The error LoadFromFile gives for `path`, "" if it loads.
template <class Map>
std::string LoadFileError(const fs::path& path) {
  Map map;
  try {
    map.LoadFromFile(path.string());
    return "";
  } catch (const std::runtime_error& e) {
    return e.what();
  }
}

class MapChecksumTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("novelty_map_checksum_" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(MapChecksumTest, ASavedMapEndsInAChecksumThatMatches) {
  CAppearanceMap map;
  map.insertObservation(Observation(Frames()[0]));
  const fs::path file = dir_ / "a.appearance_map";
  map.SaveToFile(file.string());
  EXPECT_EQ(CheckMapChecksum(file.string()), MapChecksum::kMatches);
  const std::vector<char> bytes = FileBytes(file);
  ASSERT_GT(bytes.size(), 12u);
  EXPECT_EQ(std::string(bytes.end() - 12, bytes.end() - 4), "NVMAPCRC");
  EXPECT_EQ(LoadFileError<CAppearanceMap>(file), "");
}

// The probe: 12 of 14 random bit flips in an object database loaded without a word.
// Now every flip outside the trailer's eight marker bytes is an error naming the file; a flip
// in the marker leaves the content as saved, which then loads unchecked, as an older file does.
TEST_F(MapChecksumTest, EveryChangedBitIsAnErrorNamingTheFile) {
  CObjectDatabaseMap objects;
  CAppearanceMap appearance;
  appearance.insertObservation(Observation(Frames()[0]));
  const fs::path saved_objects = dir_ / "saved.object_database";
  const fs::path saved_views = dir_ / "saved.appearance_map";
  objects.SaveToFile(saved_objects.string());
  appearance.SaveToFile(saved_views.string());
  std::mt19937 random(11);
  int errors = 0, flips = 0;
  for (const fs::path& saved : {saved_objects, saved_views}) {
    const std::vector<char> original = FileBytes(saved);
    const std::size_t marker = original.size() - 12;
    for (int k = 0; k < 14; ++k) {
      std::vector<char> bytes = original;
      std::size_t at = std::uniform_int_distribution<std::size_t>(0, bytes.size() - 1)(random);
      if (at >= marker && at < marker + 8) at = marker - 1;  // the marker: tested below
      bytes[at] ^= char(1 << std::uniform_int_distribution<int>(0, 7)(random));
      const fs::path file = dir_ / ("flipped" + saved.extension().string());
      WriteBytes(file, bytes);
      const std::string what = saved == saved_objects ? LoadFileError<CObjectDatabaseMap>(file)
                                                      : LoadFileError<CAppearanceMap>(file);
      ++flips;
      EXPECT_EQ(what.rfind(file.string() + ": ", 0), 0u) << "byte " << at << ": " << what;
      EXPECT_NE(what.find("checksum does not match"), std::string::npos) << what;
      errors += !what.empty();
    }
    std::vector<char> bytes = original;
    bytes[marker] ^= 1;
    const fs::path file = dir_ / ("marker" + saved.extension().string());
    WriteBytes(file, bytes);
    EXPECT_EQ(CheckMapChecksum(file.string()), MapChecksum::kMissing);
    EXPECT_EQ(saved == saved_objects ? LoadFileError<CObjectDatabaseMap>(file)
                                     : LoadFileError<CAppearanceMap>(file),
              "");
  }
  EXPECT_EQ(errors, flips);
}

TEST_F(MapChecksumTest, AFileWithoutTheTrailerLoadsUncheckedAsBefore) {
  CAppearanceMap map;
  map.insertObservation(Observation(Frames()[0]));
  const fs::path file = dir_ / "old.appearance_map";
  map.SaveToFile(file.string());
  std::vector<char> bytes = FileBytes(file);
  bytes.resize(bytes.size() - 12);
  WriteBytes(file, bytes);
  EXPECT_EQ(CheckMapChecksum(file.string()), MapChecksum::kMissing);
  EXPECT_EQ(LoadFileError<CAppearanceMap>(file), "");
  EXPECT_NE(LoadFileError<CAppearanceMap>(dir_).find("is a folder"), std::string::npos);
}

}  // namespace
}  // namespace novelty::mrpt_plugins
