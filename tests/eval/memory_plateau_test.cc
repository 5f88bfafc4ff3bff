#include "eval/memory_plateau.h"

#include <gtest/gtest.h>

#include "core/resident_memory.h"

namespace novelty::eval {
namespace {

TEST(MemoryPlateau, BeginsAfterTheLastNewViewAndMeasuresGrowthFromThere) {
  // Views 1, 2, 3, 3, 3, 3: the plateau begins at the third sample (frame 200).
  const std::vector<SoakSample> s = {{0, 100, 1},   {100, 150, 2}, {200, 180, 3},
                                     {300, 181, 3}, {400, 183, 3}, {500, 189, 3}};
  const MemoryPlateau p = FindMemoryPlateau(s);
  ASSERT_TRUE(p.reached);
  EXPECT_EQ(p.frame, 200);
  EXPECT_DOUBLE_EQ(p.growth, (189.0 - 180.0) / 180.0);
  // A map still growing at the end has no plateau.
  std::vector<SoakSample> growing = s;
  growing.back().views = 4;
  EXPECT_FALSE(FindMemoryPlateau(growing).reached);
  EXPECT_FALSE(FindMemoryPlateau({{0, 1, 1}}).reached);
}

// AddressSanitizer keeps one shadow byte per 8 bytes of memory: writing a block touches an eighth
// of its size more.
#if defined(__SANITIZE_ADDRESS__)
constexpr double kTouchedPerWritten = 1.125;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr double kTouchedPerWritten = 1.125;
#else
constexpr double kTouchedPerWritten = 1.0;
#endif
#else
constexpr double kTouchedPerWritten = 1.0;
#endif

TEST(ResidentMemory, GrowsByWhatIsTouched) {
  const double before = core::ResidentMegabytes();
  ASSERT_GT(before, 1.0);
  std::vector<char> block(64 << 20, 1);  // 64 MiB, every page written
  const double after = core::ResidentMegabytes();
  EXPECT_NEAR(after - before, 64.0 * kTouchedPerWritten, 8.0);
  EXPECT_EQ(block[12345], 1);
}

}  // namespace
}  // namespace novelty::eval
