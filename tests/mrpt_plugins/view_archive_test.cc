#include "mrpt_plugins/view_archive.h"

#include <gtest/gtest.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CMemoryStream.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <thread>

#include "mrpt_plugins/c_appearance_map.h"
#include "mrpt_plugins/option_table.h"
#include "tests/mrpt_plugins/clip_observations.h"

namespace novelty::mrpt_plugins {
namespace {

namespace fs = std::filesystem;

std::vector<uint8_t> Bytes(const std::function<void(mrpt::serialization::CArchive&)>& write) {
  mrpt::io::CMemoryStream m;
  auto a = mrpt::serialization::archiveFrom(m);
  write(a);
  const auto* p = static_cast<const uint8_t*>(m.getRawBufferData());
  return {p, p + m.getTotalBytesCount()};
}

// A small saved map as bytes, and where its views begin: the file is [MRPT's object header]
// [options] [views] [MRPT's end marker], and the views are what WriteViewMap writes. Written as
// file version 2 (raw images), so that values sit at known offsets; that older files load is
// tested on the way.
struct SavedMap {
  std::vector<uint8_t> file;
  std::size_t views_at = 0;
  int width = 0, height = 0, views = 0;
};

const SavedMap& Saved() {
  static const SavedMap saved = [] {
    CAppearanceMap map;
    for (int k = 0; k < 3; ++k) map.insertObservation(Observation(Frames()[k]));
    SavedMap s;
    const std::vector<uint8_t> current = Bytes([&](auto& a) { a << map; });
    const std::size_t encoded =
        Bytes([&](auto& a) { WriteViewMap(a, map.map().view_map()); }).size();
    const std::vector<uint8_t> raw = Bytes(
        [&](auto& a) { WriteViewMap(a, map.map().view_map(), MapFormatOf("CAppearanceMap", 2)); });
    s.views_at = current.size() - 1 - encoded;
    s.file.assign(current.begin(), current.begin() + std::ptrdiff_t(s.views_at));
    s.file.insert(s.file.end(), raw.begin(), raw.end());
    s.file.push_back(current.back());  // MRPT's end-of-object marker
    // MRPT's header: the class name, then the version byte.
    const std::string name = "CAppearanceMap";
    const auto at = std::search(s.file.begin(), s.file.end(), name.begin(), name.end());
    s.file[std::size_t(at - s.file.begin()) + name.size()] = 2;
    s.width = map.map().store().view(0).camera.width;
    s.height = map.map().store().view(0).camera.height;
    s.views = map.map().store().size();
    return s;
  }();
  return saved;
}

// Offsets in the first view (view_archive.cc's layout): count, camera, pose, anchor, depth, planes
// ("ab_sigma" CV_16FC7, then "tau" CV_32FC3, in name order).
struct Layout {
  std::size_t camera, anchor, depth_data, plane_count, ab_name, ab_data, tau_data;
};
Layout FirstView() {
  const SavedMap& s = Saved();
  const std::size_t px = std::size_t(s.width) * s.height;
  Layout l{};
  l.camera = s.views_at + 4;
  l.anchor = l.camera + 8 + 32 + 96;
  l.depth_data = l.anchor + 96 + 12;
  l.plane_count = l.depth_data + 4 * px;
  l.ab_name = l.plane_count + 4;
  l.ab_data = l.ab_name + 4 + 8 + 12;
  l.tau_data = l.ab_data + 14 * px + 4 + 3 + 12;
  return l;
}

template <class T>
void Poke(std::vector<uint8_t>& bytes, std::size_t at, T value) {
  std::memcpy(bytes.data() + at, &value, sizeof(T));
}

// Writes `bytes` as a map file and loads it into a map holding one frame: the error, which must
// be one line naming the file, and the map must keep its view.
std::string LoadBytesError(const std::vector<uint8_t>& bytes) {
  const fs::path file = fs::temp_directory_path() / "novelty_corrupt.appearance_map";
  {
    mrpt::io::CFileGZOutputStream out(file.string());
    out.Write(bytes.data(), bytes.size());
  }
  CAppearanceMap map;
  map.insertObservation(Observation(Frames()[0]));
  std::string what;
  try {
    map.LoadFromFile(file.string());
  } catch (const std::runtime_error& e) {
    what = e.what();
  }
  EXPECT_EQ(map.map().store().size(), 1) << "a failed load changed the map";
  EXPECT_EQ(what.rfind(file.string() + ": ", 0), 0u) << what;
  EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  fs::remove(file);
  return what;
}

TEST(MapFiles, TheUntouchedBytesLoad) {
  const fs::path file = fs::temp_directory_path() / "novelty_untouched.appearance_map";
  {
    mrpt::io::CFileGZOutputStream out(file.string());
    out.Write(Saved().file.data(), Saved().file.size());
  }
  CAppearanceMap map;
  map.LoadFromFile(file.string());
  EXPECT_EQ(map.map().store().size(), Saved().views);
  EXPECT_GE(Saved().views, 2);
  fs::remove(file);
}

TEST(MapFiles, CorruptValuesAreRefusedNamingViewAndPlane) {
  const Layout l = FirstView();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  struct Case {
    const char* what;
    std::function<void(std::vector<uint8_t>&)> corrupt;
    const char* says;
  };
  const Case cases[] = {
      {"NaN anchor", [&](auto& b) { Poke(b, l.anchor, std::numeric_limits<double>::quiet_NaN()); },
       "anchor is not a rigid transform"},
      {"negative depth", [&](auto& b) { Poke(b, l.depth_data, -1.0f); },
       "view 0: 1 negative or infinite depths"},
      {"NaN alpha", [&](auto& b) { Poke(b, l.ab_data, uint16_t(0x7E00)); },
       "view 0: plane 'ab_sigma' holds an invalid value"},
      {"zero beta", [&](auto& b) { Poke(b, l.ab_data + 2, uint16_t(0)); },
       "view 0: plane 'ab_sigma' holds an invalid value"},
      {"NaN tau", [&](auto& b) { Poke(b, l.tau_data, nan); },
       "view 0: plane 'tau' holds an invalid value"},
      {"huge camera", [&](auto& b) { Poke(b, l.camera, int32_t(100000)); },
       "implausible camera size 100000x"},
      {"plane name length 0xFFFFFFFF", [&](auto& b) { Poke(b, l.ab_name, uint32_t(0xFFFFFFFF)); },
       "plane name of 4294967295 bytes"},
      {"a plane count of 2^31-1", [&](auto& b) { Poke(b, l.plane_count, int32_t(0x7FFFFFFF)); },
       "implausible plane count"},
  };
  for (const Case& c : cases) {
    std::vector<uint8_t> bytes = Saved().file;
    c.corrupt(bytes);
    const std::string e = LoadBytesError(bytes);
    EXPECT_NE(e.find(c.says), std::string::npos) << c.what << ": " << e;
  }
}

TEST(MapFiles, ShortStringsReadWhatMrptWritesAndRefuseHugeLengths) {
  const std::vector<uint8_t> bytes = Bytes([](auto& a) { a << std::string("ab_sigma"); });
  mrpt::io::CMemoryStream m;
  m.assignMemoryNotOwn(bytes.data(), bytes.size());
  auto in = mrpt::serialization::archiveFrom(m);
  EXPECT_EQ(ReadShortString(in, 64, "name"), "ab_sigma");
  std::vector<uint8_t> huge = bytes;
  Poke(huge, 0, uint32_t(0xFFFFFFFF));
  mrpt::io::CMemoryStream h;
  h.assignMemoryNotOwn(huge.data(), huge.size());
  auto hin = mrpt::serialization::archiveFrom(h);
  EXPECT_THROW(ReadShortString(hin, 64, "name"), std::runtime_error);
}

}  // namespace
}  // namespace novelty::mrpt_plugins
