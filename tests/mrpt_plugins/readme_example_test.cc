#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "examples/surprise_from_mrpt.h"
#include "tests/mrpt_plugins/clip_observations.h"

namespace novelty::mrpt_plugins {
namespace {

std::string Between(const std::string& text, const std::string& begin, const std::string& end) {
  const auto a = text.find(begin), b = text.find(end);
  if (a == std::string::npos || b == std::string::npos || b < a) return "";
  return text.substr(a + begin.size(), b - a - begin.size());
}

std::string Read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ReadmeExample, TheReadmeQuotesTheCompiledExample) {
  const std::string code =
      Between(Read(std::string(NOVELTY_SOURCE_DIR) + "/examples/surprise_from_mrpt.cc"),
              "// README example begins\n", "// README example ends\n");
  ASSERT_FALSE(code.empty());
  const std::string readme = Read(std::string(NOVELTY_SOURCE_DIR) + "/README.md");
  const std::string quoted = Between(readme, "```cpp\n", "```\n");
  EXPECT_EQ(quoted, code) << "README.md's ```cpp block must equal examples/surprise_from_mrpt.cc";
}

// The example run on a short clip with the shipped .ini: surprise appears once the map has views.
TEST(ReadmeExample, GivesSurpriseFromTheShippedIni) {
  mrpt::maps::CMultiMetricMap maps;
  LoadMaps(std::string(NOVELTY_SOURCE_DIR) + "/share/novelty_run.ini", maps);
  cv::Mat surprise;
  for (const sim::SimulatedFrame& f : Frames()) {
    surprise = Surprise(maps, Observation(f), mrpt::poses::CPose3D());
  }
  ASSERT_EQ(surprise.size(), cv::Size(160, 120));
  int finite = 0;
  for (auto it = surprise.begin<float>(); it != surprise.end<float>(); ++it) {
    if (std::isfinite(*it)) {
      ++finite;
      ASSERT_GE(*it, 0.0f);  // a KL divergence
    }
  }
  EXPECT_GT(finite, 160 * 120 / 2);  // the arc returns over its own views
}

}  // namespace
}  // namespace novelty::mrpt_plugins
