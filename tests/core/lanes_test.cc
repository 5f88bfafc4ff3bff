#include "core/lanes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace novelty::core::lanes {
namespace {

TEST(Lanes, FloorAndCeilMatchTheStandardFunctions) {
  // Integers, halves, negatives, values just off an integer: the int-conversion trick must agree
  // with std::floor / std::ceil for all of them.
  const float values[] = {-3.0f, -2.5f, -1e-4f, 0.0f, 1e-4f, 0.5f,  1.0f,    2.999f,
                          3.0f,  7.25f, -7.25f, 1e6f, -1e6f, 15.5f, -0.999f, 123.0001f};
  F16 x = Load(values);
  const F16 f = Floor(x), c = Ceil(x);
  for (int k = 0; k < kLanes; ++k) {
    EXPECT_EQ(f[k], std::floor(values[k])) << values[k];
    EXPECT_EQ(c[k], std::ceil(values[k])) << values[k];
  }
}

TEST(Lanes, GatherIotaMinMaxAndStore) {
  // Unaligned 32-bit words at byte offsets 3k + 1 of the bytes 0, 1, 2, …
  std::vector<char> bytes(80);
  for (int i = 0; i < 80; ++i) bytes[i] = char(i);
  const I16 unaligned = GatherBytes(bytes.data(), AsInt(Iota() * 3.0f + 1.0f));
  for (int k = 0; k < kLanes; ++k) {
    const int b = 3 * k + 1;  // little endian: the first byte is the lowest
    EXPECT_EQ(unaligned[k], b | (b + 1) << 8 | (b + 2) << 16 | (b + 3) << 24) << k;
  }
  const F16 a = Iota(), b = F16{} + 7.5f;
  float out[kLanes];
  Store(out, Min(a, b));
  EXPECT_EQ(out[3], 3.0f);
  EXPECT_EQ(out[12], 7.5f);
  EXPECT_EQ(Max(a, b)[12], 12.0f);
  EXPECT_EQ(AsFloat(a > b)[12], -1.0f);  // a true lane mask is −1
  EXPECT_EQ(AsFloat(a > b)[3], 0.0f);
}

TEST(Lanes, MaskedPairsLoadAndStoreOnlyTheirLanes) {
  // 2·16 interleaved floats and a mask of every third lane: the masked-out pairs read as 0 and
  // are not overwritten; the buffer ends right after the last pair a lane may touch.
  std::vector<float> uv(2 * kLanes);
  for (int i = 0; i < 2 * kLanes; ++i) uv[std::size_t(i)] = float(i);
  I16 mask{};
  for (int k = 0; k < kLanes; k += 3) mask[k] = -1;
  F16 u, v;
  LoadMaskedPairs(uv.data(), mask, u, v);
  for (int k = 0; k < kLanes; ++k) {
    EXPECT_EQ(u[k], mask[k] ? float(2 * k) : 0.0f) << k;
    EXPECT_EQ(v[k], mask[k] ? float(2 * k + 1) : 0.0f) << k;
  }
  std::vector<float> out(2 * kLanes, -1.0f);
  StoreMaskedPairs(out.data(), u + 100.0f, v + 100.0f, mask);
  for (int k = 0; k < kLanes; ++k) {
    EXPECT_EQ(out[std::size_t(2 * k)], mask[k] ? float(2 * k) + 100.0f : -1.0f) << k;
    EXPECT_EQ(out[std::size_t(2 * k + 1)], mask[k] ? float(2 * k + 1) + 100.0f : -1.0f) << k;
  }
}

TEST(Lanes, MaskCountAndBytes) {
  I16 mask{};
  for (int k = 1; k < kLanes; k += 4) mask[k] = -1;  // lanes 1, 5, 9, 13
  EXPECT_EQ(Count(mask), 4);
  EXPECT_EQ(Bits(mask), (1u << 1) | (1u << 5) | (1u << 9) | (1u << 13));
  EXPECT_EQ(Bits(I16{} - 1), 0xFFFFu);
  EXPECT_EQ(Count(I16{}), 0);
  EXPECT_EQ(Count(I16{} - 1), kLanes);
  EXPECT_TRUE(All(I16{} - 1));
  EXPECT_FALSE(All(mask));
  I16 all_but_last = I16{} - 1;
  all_but_last[kLanes - 1] = 0;
  EXPECT_FALSE(All(all_but_last));
  uint8_t bytes[kLanes + 1];
  bytes[kLanes] = 7;  // past the sixteen: untouched
  StoreMaskBytes(bytes, mask);
  for (int k = 0; k < kLanes; ++k) EXPECT_EQ(bytes[k], mask[k] ? 255 : 0) << k;
  EXPECT_EQ(bytes[kLanes], 7);
  int8_t signed_bytes[kLanes];
  for (int k = 0; k < kLanes; ++k) signed_bytes[k] = int8_t(k * 17 - 128);
  const I16 widened = LoadBytes(signed_bytes);
  for (int k = 0; k < kLanes; ++k) EXPECT_EQ(widened[k], k * 17 - 128) << k;
}

}  // namespace
}  // namespace novelty::core::lanes
