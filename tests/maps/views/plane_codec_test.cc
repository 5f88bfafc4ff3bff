#include "maps/views/plane_codec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace novelty::views {
namespace {

// The reference rounding, in double: the value's mantissa to `bits` bits, to nearest, ties to
// even (std::nearbyint in the default mode), by scaling with its binary exponent.
double ReferenceRound(double v, int bits) {
  int e = 0;
  const double m = std::frexp(v, &e);  // v = m·2^e, 0.5 ≤ |m| < 1: 24 significant bits in a float
  return std::ldexp(std::nearbyint(std::ldexp(m, bits + 1)), e - bits - 1);
}

TEST(PlaneCodec, RoundMantissaMatchesADoublePrecisionReference) {
  std::mt19937 random(3);
  std::uniform_real_distribution<float> uniform(-300.0f, 300.0f);
  for (int bits : {6, 14, 16, 22}) {
    for (int i = 0; i < 20000; ++i) {
      const float v = uniform(random);
      const float r = RoundMantissa(v, bits);
      ASSERT_EQ(double(r), ReferenceRound(v, bits)) << v << " to " << bits << " bits";
      ASSERT_LE(std::abs(double(r) - v), std::ldexp(std::abs(v), -bits - 1));  // ≤ half a step
    }
  }
  EXPECT_EQ(RoundMantissa(1.2345f, 23), 1.2345f);  // 23 bits: exact
  EXPECT_TRUE(std::isnan(RoundMantissa(std::nanf(""), 10)));
  EXPECT_EQ(RoundMantissa(INFINITY, 10), INFINITY);
  // A carry through the mantissa moves to the next power of two.
  EXPECT_EQ(RoundMantissa(std::nextafter(2.0f, 0.0f), 10), 2.0f);
}

TEST(PlaneCodec, HalfFloatsKeepTheirBitsWithinHalfAStep) {
  cv::Mat f(1, 2000, CV_32F), h, back;
  cv::randu(f, 0.01, 500.0);
  f.convertTo(h, CV_16F);
  for (int bits : {6, 8}) {
    cv::Mat r = h.clone();
    auto* v = r.ptr<uint16_t>();
    for (int i = 0; i < r.cols; ++i) v[i] = RoundHalfMantissa(v[i], bits);
    cv::Mat exact, rounded;
    h.convertTo(exact, CV_32F);
    r.convertTo(rounded, CV_32F);
    for (int i = 0; i < r.cols; ++i) {
      const float a = exact.at<float>(i), b = rounded.at<float>(i);
      ASSERT_LE(std::abs(b - a), std::ldexp(a, -bits - 1) * 1.0001) << a << " to " << bits;
      ASSERT_EQ(double(b), ReferenceRound(a, bits)) << a;
    }
  }
}

TEST(PlaneCodec, DecodeGivesTheRoundedValuesOfEveryTypeAndChannelCount) {
  std::mt19937 random(5);
  for (const PlaneEncoding encoding : {PlaneEncoding::kPredicted, PlaneEncoding::kShuffled})
    for (int type : {CV_32FC1, CV_32FC3, CV_16FC(7), CV_8UC3, CV_8UC1, CV_16UC1, CV_32FC(5)}) {
      SCOPED_TRACE(int(encoding));
      SCOPED_TRACE(type);
      cv::Mat m(24, 32, type);
      if (CV_MAT_DEPTH(type) == CV_16F) {
        cv::Mat f(24, 32, CV_MAKETYPE(CV_32F, CV_MAT_CN(type)));
        cv::randu(f, 0.1, 100.0);
        f.convertTo(m, CV_16F);
      } else {
        cv::randu(m, 0, 255);
      }
      if (type == CV_32FC1) {
        m.at<float>(3, 4) = std::numeric_limits<float>::quiet_NaN();
        // A NaN whose payload lies in the bits rounding drops: still NaN, not ±Inf.
        const uint32_t low_payload = 0x7F800001u;
        std::memcpy(&m.at<float>(5, 6), &low_payload, 4);
      }
      PlaneCodecOptions o;
      o.encoding = encoding;
      const std::vector<uint8_t> bytes = EncodePlane(m, o);
      const cv::Mat d = DecodePlane(bytes.data(), bytes.size(), m.rows, m.cols, m.type(), encoding);
      ASSERT_EQ(d.type(), m.type());
      const std::size_t n = m.total() * m.channels();
      for (std::size_t i = 0; i < n; ++i) {
        if (m.depth() == CV_32F) {
          const float a = reinterpret_cast<const float*>(m.data)[i],
                      b = reinterpret_cast<const float*>(d.data)[i];
          if (std::isnan(a)) {
            ASSERT_TRUE(std::isnan(b));
          } else {
            ASSERT_EQ(b, RoundMantissa(a, o.float_mantissa_bits)) << i;
          }
        } else if (m.depth() == CV_16F) {
          ASSERT_EQ(reinterpret_cast<const uint16_t*>(d.data)[i],
                    RoundHalfMantissa(reinterpret_cast<const uint16_t*>(m.data)[i],
                                      o.half_mantissa_bits));
        } else {
          ASSERT_EQ(d.data[i], m.data[i]);  // integers are stored exactly
        }
      }
    }
}

// The predicted encoding is for smooth planes (depth, parameter images): there it beats grouping
// the bytes alone, and both give the same rounded values.
TEST(PlaneCodec, PredictionShrinksSmoothPlanesAndDecodesToTheSameValues) {
  cv::Mat smooth(120, 160, CV_32FC3), noise(120, 160, CV_32FC3);
  for (int y = 0; y < smooth.rows; ++y)
    for (int x = 0; x < smooth.cols; ++x)
      smooth.at<cv::Vec3f>(y, x) = cv::Vec3f(100 + 0.3f * x, 80 + 0.2f * y, 128 + 0.1f * (x - y));
  cv::randn(noise, 0, 0.5);
  smooth += noise;
  PlaneCodecOptions shuffled;
  shuffled.encoding = PlaneEncoding::kShuffled;
  const std::vector<uint8_t> p = EncodePlane(smooth), g = EncodePlane(smooth, shuffled);
  EXPECT_LT(p.size(), g.size());
  const cv::Mat a = DecodePlane(p.data(), p.size(), 120, 160, CV_32FC3),
                b = DecodePlane(g.data(), g.size(), 120, 160, CV_32FC3, PlaneEncoding::kShuffled);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
  std::printf("[ CODEC    ] smooth 160x120x3 floats: %.2f B/value predicted, %.2f grouped\n",
              double(p.size()) / smooth.total() / 3, double(g.size()) / smooth.total() / 3);
}

TEST(PlaneCodec, CorruptOrMismatchedBytesAreRefused) {
  cv::Mat m(12, 16, CV_32FC3);
  cv::randu(m, 0, 255);
  std::vector<uint8_t> bytes = EncodePlane(m);
  EXPECT_THROW(DecodePlane(bytes.data(), bytes.size(), 12, 17, CV_32FC3), std::runtime_error);
  EXPECT_THROW(DecodePlane(bytes.data(), bytes.size() / 2, 12, 16, CV_32FC3), std::runtime_error);
  bytes[bytes.size() / 2] ^= 0xFF;
  bytes[bytes.size() / 2 + 1] ^= 0x5A;
  EXPECT_THROW(DecodePlane(bytes.data(), bytes.size(), 12, 16, CV_32FC3), std::runtime_error);
  EXPECT_THROW(DecodePlane(nullptr, 0, 12, 16, CV_32FC3), std::runtime_error);
  std::vector<uint8_t> integers = EncodePlane(cv::Mat(12, 16, CV_8UC1, cv::Scalar(7)));
  integers[0] = 3;  // a dropped-bit count on an integer plane
  EXPECT_THROW(DecodePlane(integers.data(), integers.size(), 12, 16, CV_8UC1), std::runtime_error);
  EXPECT_THROW(EncodePlane(cv::Mat(4, 4, CV_64FC1)), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::views
