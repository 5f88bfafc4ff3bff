#include "eval/selectivity_csv.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace novelty::eval {
namespace {

TEST(SelectivityCsv, WritesAHeaderAndOneLinePerRegionAndFrame) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "selectivity_csv_test.csv").string();
  {
    SelectivityCsv csv(path);
    SelectivityRow r;
    r.frame = 42;
    r.region = "glass";
    r.surprise.as_db = 1.234;
    r.surprise.pas_db = 4.5;
    r.surprise.coverage = 0.9;
    r.difference.as_db = -0.5;
    r.difference.pas_db = NAN;  // undefined: blank
    csv.Add(r, "B");
  }
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(),
            "frame,phase,object,AS_surprise,PAS_surprise,AS_diff,PAS_diff,coverage\n"
            "42,B,glass,1.23,4.50,-0.50,,0.9\n");
  std::filesystem::remove(path);
  EXPECT_THROW(SelectivityCsv("/nonexistent-dir/metrics.csv"), std::runtime_error);
}

}  // namespace
}  // namespace novelty::eval
