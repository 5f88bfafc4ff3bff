#include "sim/scenario/scenario_runner.h"

#include <gtest/gtest.h>
#include <mrpt/img/CImage.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/serialization/CArchive.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "sim/scenario/scenario_parser.h"

namespace novelty::sim {
namespace {

namespace fs = std::filesystem;

Scenario Tiny(const std::string& rig) {
  std::istringstream in(R"(
name tiny
frames 8
fps 5
seed 3
camera 64 48 60
rig )" + rig + R"(
material wood phong 0.5 0.3 0.1
material white phong 0.9 0.9 0.9 0.5 40
object table box 1.0 0.6 0.70 wood at 0 0 fixed
object cup cylinder 0.04 0.1 white at 0.1 0 on table mass 0.2
lamp l1 0.5 -0.5 2.5 1.5 1.5 1.5
arc 0 0 1.5 -100 -80 0.1
)");
  return ParseScenario(in, "tiny.scn");
}

fs::path TempDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("novelty_sim_test_" + name);
  fs::remove_all(dir);
  return dir;
}

RunSummary RunInto(const Scenario& s, const fs::path& dir, std::uint64_t seed) {
  RunOptions o;
  o.out_dir = dir.string();
  o.progress = false;
  o.seed = seed;
  return RunScenario(s, o);
}

// Reads a rawlog with MRPT's own deserialisation and counts objects per class and label.
std::map<std::string, int> ReadRawlog(const fs::path& path,
                                      std::vector<mrpt::serialization::CSerializable::Ptr>* all) {
  mrpt::io::CFileGZInputStream file(path.string());
  auto arch = mrpt::serialization::archiveFrom(file);
  std::map<std::string, int> counts;
  while (true) {
    mrpt::serialization::CSerializable::Ptr obj;
    try {
      arch >> obj;
    } catch (const mrpt::serialization::CExceptionEOF&) {
      break;
    }
    auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj);
    EXPECT_TRUE(obs) << "not an observation: " << obj->GetRuntimeClass()->className;
    if (!obs) continue;
    std::string cls = obj->GetRuntimeClass()->className;
    cls = cls.substr(cls.rfind(':') + 1);  // without the namespace
    counts[cls + "/" + obs->sensorLabel]++;
    all->push_back(obj);
  }
  return counts;
}

TEST(ScenarioRunner, RgbdRawlogRoundTripsThroughMrpt) {
  const Scenario s = Tiny("rgbd");
  const fs::path dir = TempDir("rgbd");
  const RunSummary summary = RunInto(s, dir, 3);
  std::vector<mrpt::serialization::CSerializable::Ptr> objs;
  const auto counts = ReadRawlog(dir / "tiny.rawlog", &objs);
  EXPECT_EQ(counts.at("CObservation3DRangeScan/RGBD"), 8);
  EXPECT_EQ(counts.at("CObservationOdometry/ODOMETRY"), 8);
  EXPECT_EQ(counts.at("CObservationBearingRange/LED_TRACKER"), 36);  // 25 Hz over 1.4 s
  EXPECT_EQ(summary.observations, int(objs.size()));
  // Frame 5's depth, read back by MRPT from the external file, equals the ground truth PNG.
  mrpt::img::CImage::setImagesPathBase((dir / "tiny_Images").string());
  int frame = 0;
  for (const auto& o : objs) {
    auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation3DRangeScan>(o);
    if (!scan || ++frame != 5) continue;
    scan->load();
    const cv::Mat truth =
        cv::imread((dir / "groundtruth/depth/000005.png").string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(truth.type(), CV_16UC1);
    ASSERT_EQ(scan->rangeImage.rows(), truth.rows);
    int compared = 0;
    for (int r = 0; r < truth.rows; ++r) {
      for (int c = 0; c < truth.cols; ++c) {
        EXPECT_NEAR(scan->rangeImage(r, c), truth.at<uint16_t>(r, c), 1);
        compared += truth.at<uint16_t>(r, c) > 0;
      }
    }
    EXPECT_GT(compared, truth.rows * truth.cols / 2);
    EXPECT_EQ(scan->intensityImage.getWidth(), 64u);  // loads NAME_Images/000005.png
  }
  EXPECT_EQ(frame, 8);
}

TEST(ScenarioRunner, TrinocularAndStereoRigsWriteTheirObservations) {
  {
    const fs::path dir = TempDir("tri");
    RunInto(Tiny("trinocular 0.12"), dir, 3);
    std::vector<mrpt::serialization::CSerializable::Ptr> objs;
    const auto counts = ReadRawlog(dir / "tiny.rawlog", &objs);
    for (const char* label : {"CAM_LEFT", "CAM_CENTER", "CAM_RIGHT"}) {
      EXPECT_EQ(counts.at(std::string("CObservationImage/") + label), 8) << label;
    }
    // The outer cameras sit ±12 cm from the centre along the camera's x axis.
    std::map<std::string, mrpt::poses::CPose3D> poses;
    for (const auto& o : objs) {
      if (auto img = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(o)) {
        poses[img->sensorLabel] = img->cameraPose;
      }
    }
    EXPECT_NEAR((poses["CAM_RIGHT"] - poses["CAM_CENTER"]).x(), 0.12, 1e-9);
    EXPECT_NEAR((poses["CAM_LEFT"] - poses["CAM_CENTER"]).x(), -0.12, 1e-9);
  }
  {
    const fs::path dir = TempDir("stereo");
    RunInto(Tiny("stereo 0.12"), dir, 3);
    std::vector<mrpt::serialization::CSerializable::Ptr> objs;
    EXPECT_EQ(ReadRawlog(dir / "tiny.rawlog", &objs).at("CObservationStereoImages/STEREO"), 8);
  }
}

std::string FileBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ScenarioRunner, BitIdenticalOutputForTheSameSeed) {
  const Scenario s = Tiny("mono");
  const fs::path a = TempDir("same_a"), b = TempDir("same_b"), c = TempDir("other_seed");
  RunInto(s, a, 7);
  RunInto(s, b, 7);
  RunInto(s, c, 8);
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(a)) {
    if (!entry.is_regular_file()) continue;
    const fs::path rel = fs::relative(entry.path(), a);
    EXPECT_EQ(FileBytes(entry.path()), FileBytes(b / rel)) << rel;
    ++files;
  }
  EXPECT_GT(files, 8 * 4);
  EXPECT_NE(FileBytes(a / "tiny_Images/000003.png"), FileBytes(c / "tiny_Images/000003.png"));
}

// Debian's mrpt-apps must read what we write: rawlog-edit --info lists every observation.
TEST(ScenarioRunner, RawlogEditReadsTheRawlog) {
  if (std::system("command -v rawlog-edit > /dev/null 2>&1") != 0) {
    GTEST_SKIP() << "rawlog-edit (Debian package mrpt-apps) is not installed";
  }
  const fs::path dir = TempDir("rawlog_edit");
  RunInto(Tiny("rgbd"), dir, 1);
  const std::string cmd = "cd " + dir.string() + " && rawlog-edit --info -i tiny.rawlog 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string output;
  char buf[512];
  while (fgets(buf, sizeof buf, pipe)) output += buf;
  EXPECT_EQ(pclose(pipe), 0) << output;
  EXPECT_NE(output.find("Observations format               : Yes"), std::string::npos) << output;
  EXPECT_NE(output.find("RGBD /      8"), std::string::npos) << output;
  EXPECT_NE(output.find("LED_TRACKER /     36"), std::string::npos) << output;
}

}  // namespace
}  // namespace novelty::sim
