#include "core/lanes.h"

#include <gtest/gtest.h>

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>
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

// Sixteen floats that end where an unreadable page begins: a masked lane's load or store past
// the end faults instead of passing unnoticed.
class GuardedFloats {
 public:
  explicit GuardedFloats(int n) {
    page_ = std::size_t(sysconf(_SC_PAGESIZE));
    base_ = static_cast<char*>(
        mmap(nullptr, 2 * page_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0));
    if (base_ == MAP_FAILED) throw std::runtime_error("mmap failed");
    mprotect(base_ + page_, page_, PROT_NONE);
    data_ = reinterpret_cast<float*>(base_ + page_) - n;
  }
  ~GuardedFloats() { munmap(base_, 2 * page_); }
  GuardedFloats(const GuardedFloats&) = delete;
  GuardedFloats& operator=(const GuardedFloats&) = delete;
  float* data() const { return data_; }

 private:
  std::size_t page_ = 0;
  char* base_ = nullptr;
  float* data_ = nullptr;
};

// A mask whose lanes are set independently with probability `p`.
I16 RandomMask(std::mt19937& rng, double p) {
  std::bernoulli_distribution set(p);
  I16 m{};
  for (int k = 0; k < kLanes; ++k) m[k] = set(rng) ? -1 : 0;
  return m;
}

TEST(Lanes, MaskedLoadAndStoreReadAndWriteOnlyTheirLanes) {
  // The first n lanes lie inside the buffer, the rest in the guard page: only a load or store
  // that touches a masked-out lane faults. Every prefix, as at a row's end, and random masks.
  std::mt19937 rng(7);
  for (int n = 1; n <= kLanes; ++n) {
    GuardedFloats buffer(n);
    for (int k = 0; k < n; ++k) buffer.data()[k] = float(10 * k + n);
    const I16 inside = AsFloat(AsInt(Iota())) < float(n);
    for (int trial = 0; trial < 8; ++trial) {
      const I16 mask = (trial == 0 ? I16{} - 1 : RandomMask(rng, 0.6)) & inside;
      const F16 v = LoadMasked(buffer.data(), mask);
      for (int k = 0; k < kLanes; ++k) {
        EXPECT_EQ(v[k], mask[k] ? float(10 * k + n) : 0.0f) << "n " << n << " lane " << k;
      }
      StoreMasked(buffer.data(), v + 1.0f, mask);
      for (int k = 0; k < n; ++k) {
        EXPECT_EQ(buffer.data()[k], float(10 * k + n) + (mask[k] ? 1.0f : 0.0f)) << k;
      }
      for (int k = 0; k < n; ++k) buffer.data()[k] = float(10 * k + n);
    }
  }
}

TEST(Lanes, HalfToFloatAgreesWithTheScalarFormForEveryHalf) {
  // All 65 536 half floats, sixteen at a time, against the bit-level scalar conversion (which
  // the IEEE definition checks below): equal bits, NaN payloads included.
  for (uint32_t h0 = 0; h0 < 65536; h0 += kLanes) {
    I16 bits;
    for (int k = 0; k < kLanes; ++k) bits[k] = int32_t(h0 + uint32_t(k)) | (0x5A5A << 16);
    const F16 f = HalfToFloat(bits);
    for (int k = 0; k < kLanes; ++k) {
      const float scalar = HalfToFloat(h0 + uint32_t(k)), vector = f[k];
      uint32_t a, b;
      std::memcpy(&a, &vector, 4);
      std::memcpy(&b, &scalar, 4);
      if (std::isnan(scalar)) {
        ASSERT_TRUE(std::isnan(f[k])) << h0 + uint32_t(k);
      } else {
        ASSERT_EQ(a, b) << h0 + uint32_t(k);
      }
    }
  }
  // IEEE 754 binary16: 1, −2, the largest (65504), the smallest normal and subnormal, infinity.
  EXPECT_EQ(HalfToFloat(0x3C00u), 1.0f);
  EXPECT_EQ(HalfToFloat(0xC000u), -2.0f);
  EXPECT_EQ(HalfToFloat(0x7BFFu), 65504.0f);
  EXPECT_EQ(HalfToFloat(0x0400u), std::ldexp(1.0f, -14));
  EXPECT_EQ(HalfToFloat(0x0001u), std::ldexp(1.0f, -24));
  EXPECT_EQ(HalfToFloat(0x7C00u), std::numeric_limits<float>::infinity());
}

TEST(Lanes, MaskReductionsAgreeWithLaneByLaneDefinitions) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int32_t> value(-1000000, 1000000);
  for (int trial = 0; trial < 2000; ++trial) {
    const I16 mask = RandomMask(rng, trial % 4 == 0 ? 0.05 : 0.5);
    I16 v;
    for (int k = 0; k < kLanes; ++k) v[k] = trial == 1 ? INT32_MIN + k : value(rng);
    unsigned bits = 0;
    int lo = std::numeric_limits<int>::max(), hi = std::numeric_limits<int>::min(), count = 0;
    for (int k = 0; k < kLanes; ++k) {
      if (!mask[k]) continue;
      bits |= 1u << k;
      lo = std::min(lo, v[k]);
      hi = std::max(hi, v[k]);
      ++count;
    }
    ASSERT_EQ(Bits(mask), bits);
    ASSERT_EQ(Count(mask), count);
    ASSERT_EQ(Any(mask), count > 0);
    ASSERT_EQ(All(mask), count == kLanes);
    if (count > 0) {
      ASSERT_EQ(MinLane(v, mask), lo) << trial;
      ASSERT_EQ(MaxLane(v, mask), hi) << trial;
    }
  }
}

TEST(Lanes, GatherWidenNarrowAndScatterAgreeWithLaneByLaneDefinitions) {
  std::mt19937 rng(13);
  std::vector<char> bytes(4096);
  for (char& b : bytes) b = char(rng());
  std::uniform_int_distribution<int> offset(0, 4096 - 4);
  for (int trial = 0; trial < 500; ++trial) {
    I16 at;
    for (int k = 0; k < kLanes; ++k) at[k] = offset(rng);
    const I16 g = GatherBytes(bytes.data(), at);
    for (int k = 0; k < kLanes; ++k) {
      int32_t word;
      std::memcpy(&word, bytes.data() + at[k], 4);
      ASSERT_EQ(g[k], word) << k;
    }
    int8_t small[kLanes];
    for (int8_t& b : small) b = int8_t(rng());
    const I16 widened = LoadBytes(small);
    for (int k = 0; k < kLanes; ++k) ASSERT_EQ(widened[k], small[k]);
    const I16 mask = RandomMask(rng, 0.5);
    uint8_t narrowed[kLanes];
    StoreMaskBytes(narrowed, mask);
    for (int k = 0; k < kLanes; ++k) ASSERT_EQ(narrowed[k], mask[k] ? 255 : 0);
    // Scatter to a permutation of 0…31 spread over twice the lanes.
    std::vector<int> slots(2 * kLanes);
    for (int i = 0; i < 2 * kLanes; ++i) slots[std::size_t(i)] = i;
    std::shuffle(slots.begin(), slots.end(), rng);
    I16 index;
    for (int k = 0; k < kLanes; ++k) index[k] = slots[std::size_t(k)];
    std::vector<float> out(2 * kLanes, -1.0f);
    Scatter(out.data(), index, Iota() + 0.5f);
    for (int k = 0; k < kLanes; ++k) ASSERT_EQ(out[std::size_t(index[k])], float(k) + 0.5f);
    int untouched = 0;
    for (float o : out) untouched += o == -1.0f;
    ASSERT_EQ(untouched, kLanes);
  }
}

TEST(Lanes, ReciprocalIsWithinTwoUlpsOfTheQuotient) {
  // Against 1/x in double over 12 decades and both signs.
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> exponent(-6.0f, 6.0f);
  for (int trial = 0; trial < 1000; ++trial) {
    F16 x;
    for (int k = 0; k < kLanes; ++k) x[k] = (k % 2 ? -1.0f : 1.0f) * std::pow(10.0f, exponent(rng));
    const F16 r = Reciprocal(x);
    for (int k = 0; k < kLanes; ++k) {
      const double exact = 1.0 / double(x[k]);
      ASSERT_LE(std::abs(double(r[k]) - exact), 2.0 * std::ldexp(std::abs(exact), -23)) << x[k];
    }
  }
}

}  // namespace
}  // namespace novelty::core::lanes
