// Writes the seed corpora the fuzzers start from, made by the code they fuzz (so that seeds follow
// the formats): fuzz_seeds OUT_DIR SOURCE_DIR
//   OUT/map_file/   a small appearance map, a differencing map and an object database (class
//                   byte + plain archive)
//   OUT/rawlog/     a small plain rawlog: robot poses and RGB-D frames with their images inside
//   OUT/scenario/   the shipped scenarios        OUT/ini/   the shipped .ini files
//   and in each, the inputs of tests/fuzz/regressions/<target>/ that a fuzzer once failed on
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/serialization/CArchive.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "mrpt_plugins/c_appearance_map.h"
#include "mrpt_plugins/c_differencing_map.h"
#include "mrpt_plugins/c_object_database_map.h"
#include "sensors/rawlog/camera_pose_observation.h"
#include "sensors/rawlog/rgbd_observation.h"
#include "sim/scenario/scenario_parser.h"
#include "sim/scenario/simulate_frames.h"

namespace fs = std::filesystem;
using namespace novelty;

namespace {

// Four frames at 24×18: seeds of a few kilobytes, which the fuzzers mutate thousands of times a
// second.
std::vector<sim::SimulatedFrame> TinyFrames() {
  std::istringstream in(R"(
name seed
frames 4
fps 7
camera 24 18 60
rig rgbd
mount 0.0 0.0 1.10 90 16
material wood phong 0.45 0.28 0.14 0.1 20
object table box 1.2 0.8 0.72 wood at 0 0 fixed
lamp l1 -1.0 0.8 2.6 2.2 2.1 1.9
arc 0 0 1.6 -100 -60 0.3
)");
  return sim::SimulateFrames(sim::ParseScenario(in, "seed.scn"));
}

mrpt::obs::CObservation3DRangeScan Observation(const sim::SimulatedFrame& f) {
  return sensors::MakeRgbdObservation(f.time, f.rgb, f.depth,
                                      core::PinholeCamera::FromFov(24, 18, 60.0 * M_PI / 180),
                                      f.T_world_cam);
}

void WriteMap(const mrpt::serialization::CSerializable& map, uint8_t class_byte,
              const fs::path& path) {
  mrpt::io::CMemoryStream m;
  auto a = mrpt::serialization::archiveFrom(m);
  a << map;
  std::ofstream out(path, std::ios::binary);
  out.put(char(class_byte));
  out.write(static_cast<const char*>(m.getRawBufferData()), std::streamsize(m.getTotalBytesCount()));
}

void CopyAll(const fs::path& from, const std::string& extension, const fs::path& to) {
  for (const auto& e : fs::directory_iterator(from))
    if (e.path().extension() == extension)
      fs::copy_file(e.path(), to / e.path().filename(), fs::copy_options::overwrite_existing);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: fuzz_seeds OUT_DIR SOURCE_DIR\n");
    return 2;
  }
  const fs::path out = argv[1], source = argv[2];
  for (const char* d : {"map_file", "rawlog", "scenario", "ini"}) {
    fs::create_directories(out / d);
    fs::create_directories(out / (std::string(d) + "_new"));  // what the fuzzers find
  }
  const std::vector<sim::SimulatedFrame> frames = TinyFrames();
  mrpt_plugins::CAppearanceMap appearance;
  mrpt_plugins::CDifferencingMap differencing;
  {
    mrpt::io::CFileOutputStream file((out / "rawlog" / "seed.rawlog").string());
    auto rawlog = mrpt::serialization::archiveFrom(file);
    for (const sim::SimulatedFrame& f : frames) {
      const auto scan = Observation(f);
      appearance.insertObservation(scan);
      differencing.insertObservation(scan);
      rawlog << sensors::MakeCameraPoseObservation(f.time, f.T_world_cam,
                                                   Eigen::Isometry3d::Identity(), "TRACKER",
                                                   0.001, 0.003)
             << scan;
    }
  }
  WriteMap(appearance, 0, out / "map_file" / "appearance");
  WriteMap(differencing, 1, out / "map_file" / "differencing");
  {  // an object database of two objects, five features each, one of them seen twice
    mrpt_plugins::CObjectDatabaseMap objects;
    objects::FeatureDatabase& db = objects.database();
    cv::Mat d(10, 64, CV_32F);
    cv::RNG(1).fill(d, cv::RNG::NORMAL, 0.0, 1.0);
    db.AddFeatures(d.rowRange(0, 5), db.AddObject(),
                   std::vector<Eigen::Vector3d>(5, Eigen::Vector3d(1, 2, 0.8)));
    db.AddFeatures(d.rowRange(5, 10), db.AddObject());
    db.Recognize(d.rowRange(0, 2));
    WriteMap(objects, 2, out / "map_file" / "object_database");
  }
  CopyAll(source / "share" / "scenarios", ".scn", out / "scenario");
  CopyAll(source / "share", ".ini", out / "ini");
  fs::copy_file(source / "examples" / "maps.ini", out / "ini" / "example_maps.ini",
                fs::copy_options::overwrite_existing);
  // Inputs the fuzzers once failed on (tests/fuzz/regressions/<target>/): every run retries them.
  for (const char* d : {"map_file", "rawlog", "scenario", "ini"}) {
    const fs::path found = source / "tests" / "fuzz" / "regressions" / d;
    if (!fs::is_directory(found)) continue;
    for (const auto& e : fs::directory_iterator(found))
      fs::copy_file(e.path(), out / d / ("regression_" + e.path().filename().string()),
                    fs::copy_options::overwrite_existing);
  }
  std::printf("fuzz_seeds: corpora in %s\n", out.c_str());
  return 0;
}
