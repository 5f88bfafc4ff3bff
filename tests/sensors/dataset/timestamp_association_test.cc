#include "sensors/dataset/timestamp_association.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace novelty::sensors {
namespace {

// Hand-checked: rgb at 30 Hz, depth 5–12 ms later, one depth frame missing, one extra.
//   rgb   1.000 1.033 1.067 1.100 1.133
//   depth 1.005 1.045       1.107 1.140 1.300
// 1.067 has no depth within 20 ms (1.045 is 22 ms before, 1.107 40 ms after); 1.300 matches none.
TEST(AssociateByTime, PairsTheNearestWithinTheTolerance) {
  const std::vector<double> rgb = {1.000, 1.033, 1.067, 1.100, 1.133};
  const std::vector<double> depth = {1.045, 1.005, 1.107, 1.140, 1.300};  // not in time order
  const auto pairs = AssociateByTime(rgb, depth, 0.02);
  const std::vector<std::pair<int, int>> expected = {{0, 1}, {1, 0}, {3, 2}, {4, 3}};
  EXPECT_EQ(pairs, expected);
  // 30 ms: 1.067 is within reach of 1.045 (22 ms), but 1.033 is closer to it (12 ms) and keeps
  // it; 1.133 could take 1.107 (26 ms), which 1.100 holds at 7 ms.
  const auto wider = AssociateByTime(rgb, depth, 0.03);
  EXPECT_EQ(wider, expected);
  EXPECT_TRUE(AssociateByTime(rgb, depth, 0.0).empty());
  EXPECT_THROW(AssociateByTime(rgb, depth, -1), std::invalid_argument);
}

// Each entry once, the closest pair first: two rgb frames near one depth frame.
TEST(AssociateByTime, TheCloserPairWinsAContestedEntry) {
  const auto pairs = AssociateByTime({10.00, 10.01}, {10.008}, 0.05);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0], std::make_pair(1, 0));
}

TEST(ReadTimedLines, ReadsTumListsAndNamesTheBadLine) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("novelty_timed_lines_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string good = (dir / "rgb.txt").string();
  std::ofstream(good) << "# color images\n# timestamp filename\n1341841278.8427 rgb/a.jpg\n"
                         "\n1341841279.5107 rgb/b.jpg\n";
  const auto lines = ReadTimedLines(good, 1);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_DOUBLE_EQ(lines[1].time, 1341841279.5107);
  EXPECT_EQ(lines[1].fields[0], "rgb/b.jpg");
  EXPECT_EQ(lines[1].line, 5);
  const std::string bad = (dir / "groundtruth.txt").string();
  std::ofstream(bad) << "1.0 1 2 3 0 0 0 1\n2.0 1 2 3 0 0 0\n";
  try {
    ReadTimedLines(bad, 7);
    ADD_FAILURE();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("groundtruth.txt:2: expected a timestamp and 7 fields"),
              std::string::npos)
        << e.what();
  }
  std::ofstream(bad) << "x1.0 a\n";
  EXPECT_THROW(ReadTimedLines(bad, 1), std::runtime_error);
  std::ofstream(bad) << "# only comments\n";
  EXPECT_THROW(ReadTimedLines(bad, 1), std::runtime_error);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace novelty::sensors
