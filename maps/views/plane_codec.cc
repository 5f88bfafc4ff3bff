#include "maps/views/plane_codec.h"

#include <zstd.h>

#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

namespace novelty::views {

namespace {

// `bits` (an IEEE value of `mantissa` mantissa bits and exponent mask `exponent`) with the lowest
// `drop` mantissa bits rounded away: to nearest, ties to even; a carry into the exponent is the
// right result. NaN and ±Inf unchanged.
template <class U>
U RoundBits(U bits, U exponent, int drop) {
  if (drop <= 0 || (bits & exponent) == exponent) return bits;
  const U half = U(U(1) << (drop - 1)), lsb = U((bits >> drop) & 1u);
  return U((bits + half - 1 + lsb) & ~U((U(1) << drop) - 1));
}

}  // namespace

float RoundMantissa(float value, int bits) {
  uint32_t u;
  std::memcpy(&u, &value, 4);
  u = RoundBits<uint32_t>(u, 0x7F800000u, 23 - bits);
  std::memcpy(&value, &u, 4);
  return value;
}

uint16_t RoundHalfMantissa(uint16_t half, int bits) {
  return RoundBits<uint16_t>(half, 0x7C00u, 10 - bits);
}

std::vector<uint8_t> EncodePlane(const cv::Mat& plane, const PlaneCodecOptions& options) {
  const cv::Mat m = plane.clone();  // rounded in place, continuous
  const std::size_t element = m.elemSize1(), n = m.total() * m.channels();
  if (m.depth() == CV_32F) {
    auto* v = reinterpret_cast<float*>(m.data);
    for (std::size_t i = 0; i < n; ++i) v[i] = RoundMantissa(v[i], options.float_mantissa_bits);
  } else if (m.depth() == CV_16F) {
    auto* v = reinterpret_cast<uint16_t*>(m.data);
    for (std::size_t i = 0; i < n; ++i) v[i] = RoundHalfMantissa(v[i], options.half_mantissa_bits);
  }
  // Byte b of every value together: the compressor sees runs of similar bytes.
  std::vector<uint8_t> shuffled(n * element);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t b = 0; b < element; ++b) shuffled[b * n + i] = m.data[i * element + b];
  // With zstd's checksum: a damaged plane is refused, not decoded into other values.
  const std::unique_ptr<ZSTD_CCtx, std::size_t (*)(ZSTD_CCtx*)> context(ZSTD_createCCtx(),
                                                                         ZSTD_freeCCtx);
  ZSTD_CCtx_setParameter(context.get(), ZSTD_c_compressionLevel, options.zstd_level);
  ZSTD_CCtx_setParameter(context.get(), ZSTD_c_checksumFlag, 1);
  std::vector<uint8_t> out(ZSTD_compressBound(shuffled.size()));
  const std::size_t size =
      ZSTD_compress2(context.get(), out.data(), out.size(), shuffled.data(), shuffled.size());
  if (ZSTD_isError(size)) throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(size));
  out.resize(size);
  return out;
}

cv::Mat DecodePlane(const uint8_t* bytes, std::size_t size, int rows, int cols, int type) {
  const std::size_t expected = std::size_t(rows) * cols * CV_ELEM_SIZE(type);
  const unsigned long long content = ZSTD_getFrameContentSize(bytes, size);
  if (content != expected)  // also ZSTD_CONTENTSIZE_ERROR / _UNKNOWN
    throw std::runtime_error("compressed plane is corrupt or of another size");
  cv::Mat m(rows, cols, type);
  const std::size_t element = m.elemSize1(), n = m.total() * m.channels();
  std::vector<uint8_t> shuffled(expected);
  const std::size_t got = ZSTD_decompress(shuffled.data(), shuffled.size(), bytes, size);
  if (ZSTD_isError(got) || got != expected) throw std::runtime_error("compressed plane is corrupt");
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t b = 0; b < element; ++b) m.data[i * element + b] = shuffled[b * n + i];
  return m;
}

}  // namespace novelty::views
