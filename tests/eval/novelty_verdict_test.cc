#include "eval/novelty_verdict.h"

#include <gtest/gtest.h>

#include <limits>

namespace novelty::eval {
namespace {

// Frames 1…n, predicted from frame 2 on, with the given tail surprise per frame.
struct JudgedRun {
  std::vector<int> numbers;
  std::vector<PredictionQuality> frames;
  explicit JudgedRun(const std::vector<double>& tail) {
    for (std::size_t k = 0; k < tail.size(); ++k) {
      numbers.push_back(int(k) + 1);
      PredictionQuality q;
      q.coverage = k == 0 ? 0.0 : 0.8;
      q.tail_surprise = k == 0 ? std::numeric_limits<double>::quiet_NaN() : tail[k];
      frames.push_back(q);
    }
  }
};

// Levels 4, 5, 6 repeated: median 5; at or below it deviations 1 and 0 in equal numbers, their
// median 0.5, σ̂ = 0.7413; z = 3 puts the threshold at 7.22.
std::vector<double> Level(int n) {
  std::vector<double> v = {0};
  for (int k = 0; k < n; ++k) v.push_back(4.0 + k % 3);
  return v;
}

TEST(NoveltyVerdict, ThresholdIsMedianPlusZRobustDeviations) {
  const JudgedRun run(Level(30));
  const NoveltyVerdict v = JudgeNovelty(run.numbers, run.frames);
  EXPECT_DOUBLE_EQ(v.median_nats, 5.0);
  EXPECT_DOUBLE_EQ(v.sigma_nats, 0.5 * 1.4826);
  EXPECT_DOUBLE_EQ(v.threshold_nats, 5.0 + 3 * 0.5 * 1.4826);
  EXPECT_TRUE(v.stretches.empty());
  // Frames above the median do not widen the spread: raising them leaves the threshold.
  std::vector<double> raised = Level(30);
  for (double& x : raised) x = x > 5 ? 100 : x;
  const JudgedRun high(raised);
  EXPECT_DOUBLE_EQ(JudgeNovelty(high.numbers, high.frames).threshold_nats, v.threshold_nats);
  EXPECT_EQ(v.first_frame, 2);  // frame 1 was not predicted
  EXPECT_EQ(v.last_frame, 31);
  EXPECT_EQ(v.frames_judged, 30);
  const std::string s = v.Sentence();
  EXPECT_EQ(s.rfind("Nothing new in frames 2–31 (30 frames judged; ", 0), 0u) << s;
  // A still scene: σ̂ 0, and the floor keeps the threshold from the median itself.
  const JudgedRun still({0, 1, 1, 1, 1, 1.2, 1.3});
  const NoveltyVerdict floor = JudgeNovelty(still.numbers, still.frames);
  EXPECT_DOUBLE_EQ(floor.threshold_nats, 5.0);
  EXPECT_TRUE(floor.at_floor);
  EXPECT_FALSE(v.at_floor);
  EXPECT_NE(floor.Sentence().find("the floor"), std::string::npos) << floor.Sentence();
  EXPECT_NE(v.Sentence().find("median 5.0 nats plus 3 × its robust deviation 0.7"),
            std::string::npos)
      << v.Sentence();
}

TEST(NoveltyVerdict, StretchesOfAtLeastMinFramesWithTheirPeaks) {
  std::vector<double> tail = Level(30);
  tail[5] = tail[6] = 12;               // frames 6-7
  tail[10] = 9.5;                       // frame 11 alone: not a stretch of 2
  tail[15] = 7.0;                       // frame 16: below 7.22
  tail[20] = tail[21] = tail[22] = 20;  // frames 21-23
  tail[21] = 30;
  const JudgedRun run(tail);
  NoveltyVerdictOptions two;
  two.min_frames = 2;
  const NoveltyVerdict v = JudgeNovelty(run.numbers, run.frames, two);
  ASSERT_EQ(v.stretches.size(), 2u);
  EXPECT_EQ(v.stretches[0].first, 6);
  EXPECT_EQ(v.stretches[0].last, 7);
  EXPECT_EQ(v.stretches[0].peak_nats, 12.0);
  EXPECT_EQ(v.stretches[1].first, 21);
  EXPECT_EQ(v.stretches[1].last, 23);
  EXPECT_EQ(v.stretches[1].peak_nats, 30.0);
  const std::string s = v.Sentence();
  EXPECT_EQ(s.rfind("Something new in frames 6–7 (peak 12.0 nats) and 21–23 (peak 30.0 nats) "
                    "of the 30 frames judged in 2–31 (",
                    0),
            0u)
      << s;
  const NoveltyVerdict one = JudgeNovelty(run.numbers, run.frames);
  ASSERT_EQ(one.stretches.size(), 3u) << "one frame is a stretch by default";
  EXPECT_NE(one.Sentence().find(", 11 (peak 9.5 nats) and 21–23"), std::string::npos)
      << one.Sentence();
}

TEST(NoveltyVerdict, AnUnpredictedFrameNeitherBreaksNorExtendsAStretch) {
  std::vector<double> tail = Level(20);
  tail[5] = tail[6] = tail[7] = 15;
  JudgedRun run(tail);
  run.frames[6].coverage = 0.0;  // frame 7: a new place, no prediction
  const NoveltyVerdict v = JudgeNovelty(run.numbers, run.frames);
  ASSERT_EQ(v.stretches.size(), 1u);
  EXPECT_EQ(v.stretches[0].first, 6);
  EXPECT_EQ(v.stretches[0].last, 8);
  EXPECT_EQ(v.frames_judged, 19);
}

TEST(NoveltyVerdict, NothingPredictedAndBadOptions) {
  const JudgedRun run({0});
  EXPECT_EQ(JudgeNovelty(run.numbers, run.frames).Sentence(),
            "No frame was predicted by the map: nothing could be judged.");
  NoveltyVerdictOptions o;
  o.z = -1;
  EXPECT_THROW(JudgeNovelty(run.numbers, run.frames, o), std::invalid_argument);
  o = {};
  o.min_frames = 0;
  EXPECT_THROW(o.Check(), std::invalid_argument);
  o = {};
  o.tail_pixels = 0;
  EXPECT_THROW(o.Check(), std::invalid_argument);
  o = {};
  o.floor_nats = std::numeric_limits<double>::infinity();
  EXPECT_THROW(o.Check(), std::invalid_argument);
  EXPECT_THROW(JudgeNovelty({1, 2}, run.frames), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::eval
