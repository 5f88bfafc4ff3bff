#include "eval/selectivity_findings.h"

#include <gtest/gtest.h>

#include <limits>

#include "tests/eval/selectivity_row.h"

namespace novelty::eval {
namespace {

TEST(MeanOver, AveragesTheRegionsFiniteFramesInRange) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<SelectivityRow> rows = {Row(9, "cup", 9, 9, 9, 9),      // before the range
                                            Row(10, "cup", 1, 2, 3, 4),     //
                                            Row(11, "glass", 7, 7, 7, 7),   // another region
                                            Row(12, "cup", nan, 0, 0, 0),   // no measure: left out
                                            Row(13, "cup", -3, 0, -1, -2),  //
                                            Row(21, "cup", 9, 9, 9, 9)};    // after
  const MeanSelectivity m = MeanOver(rows, "cup", 10, 20);
  EXPECT_EQ(m.frames, 2);
  EXPECT_DOUBLE_EQ(m.as_surprise, -1.0);
  EXPECT_DOUBLE_EQ(m.pas_surprise, 1.0);
  EXPECT_DOUBLE_EQ(m.as_difference, 1.0);
  EXPECT_DOUBLE_EQ(m.pas_difference, 1.0);
  EXPECT_EQ(MeanOver(rows, "arm", 0, 100).frames, 0);
}

TEST(Evaluate, DecidesEachClaimFromTheMeans) {
  const std::vector<SelectivityRow> rows = {Row(1, "glass", -0.4, 3.2, -1.9, 1.4),
                                            Row(2, "cup", -0.4, 2.7, -1.5, -0.1),
                                            Row(3, "removed", -0.4, 2.5, 1.8, 3.1)};
  const auto holds = [&](const std::string& region, Claim claim, int first, int last) {
    return Evaluate(rows, {region, region, claim, first, last}).holds;
  };
  EXPECT_TRUE(holds("glass", Claim::kSurpriseMoreSelective, 1, 1));
  EXPECT_FALSE(holds("cup", Claim::kBothDetect, 2, 2));  // differencing's PAS is below 0 dB
  EXPECT_TRUE(holds("cup", Claim::kSurpriseMoreSelective, 2, 2));
  EXPECT_TRUE(holds("removed", Claim::kSurpriseLessSelective, 3, 3));
  EXPECT_FALSE(holds("removed", Claim::kSurpriseMoreSelective, 3, 3));
  EXPECT_FALSE(holds("glass", Claim::kSurpriseMoreSelective, 5, 9));  // no frame in range
  const FindingResult r = Evaluate(rows, {"", "removed", Claim::kSurpriseLessSelective, 1, 3});
  EXPECT_EQ(r.mean.frames, 1);
  EXPECT_DOUBLE_EQ(r.mean.as_difference, 1.8);
}

TEST(SurpriseLosesLess, ComparesTheDropsOfPeakSelectivity) {
  MeanSelectivity full, half;
  full.frames = half.frames = 10;
  full.pas_surprise = 4.2, full.pas_difference = 2.6;
  half.pas_surprise = 3.8, half.pas_difference = 0.3;  // drops 0.4 against 2.3 dB
  EXPECT_TRUE(SurpriseLosesLess(full, half));
  half.pas_surprise = 1.0;  // drops 3.2 dB
  EXPECT_FALSE(SurpriseLosesLess(full, half));
  half.frames = 0;
  EXPECT_FALSE(SurpriseLosesLess(full, half));
}

}  // namespace
}  // namespace novelty::eval
