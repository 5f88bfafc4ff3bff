#include "maps/views/plane_codec.h"

#include <zstd.h>

#include <algorithm>
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

// The low bits a value of `depth` loses to rounding.
int DroppedBits(int depth, const PlaneCodecOptions& o) {
  if (o.float_mantissa_bits < 1 || o.float_mantissa_bits > 23 || o.half_mantissa_bits < 1 ||
      o.half_mantissa_bits > 10) {
    throw std::invalid_argument(
        "PlaneCodecOptions: mantissa bits must be 1…23 (float), 1…10 (half)");
  }
  if (depth == CV_32F) return 23 - o.float_mantissa_bits;
  if (depth == CV_16F) return 10 - o.half_mantissa_bits;
  return 0;
}

// Every value of the continuous `m` as an unsigned integer of its bits, rounded and shifted
// right by `drop`. A NaN becomes the quiet NaN whose payload is its top mantissa bit, which
// rounding keeps: a payload in the dropped bits would come back as ±Inf.
void Quantize(const cv::Mat& m, int drop, std::vector<uint32_t>& q) {
  const std::size_t n = m.total() * m.channels();
  q.resize(n);
  const int depth = m.depth();
  if (m.elemSize1() == 4) {
    const auto* v = reinterpret_cast<const uint32_t*>(m.data);
    for (std::size_t i = 0; i < n; ++i) {
      uint32_t u = v[i];
      if (depth == CV_32F) {
        u = (u & 0x7FFFFFFFu) > 0x7F800000u ? 0x7FC00000u
                                            : RoundBits<uint32_t>(u, 0x7F800000u, drop);
      }
      q[i] = u >> drop;
    }
  } else if (m.elemSize1() == 2) {
    const auto* v = reinterpret_cast<const uint16_t*>(m.data);
    for (std::size_t i = 0; i < n; ++i) {
      uint16_t u = v[i];
      if (depth == CV_16F)
        u = (u & 0x7FFFu) > 0x7C00u ? uint16_t(0x7E00u) : RoundBits<uint16_t>(u, 0x7C00u, drop);
      q[i] = uint32_t(u) >> drop;
    }
  } else {
    for (std::size_t i = 0; i < n; ++i) q[i] = m.data[i];
  }
}

// LOCO-I's median predictor: of the left a, upper b and upper-left c neighbours, a or b at an
// edge across them (c beyond both), else the plane through them (a + b − c): the median of
// a, b and a + b − c, i.e. a + b − c clamped to [min(a, b), max(a, b)] — branch-free, since
// residual images are noise to a branch predictor. S: a signed type that holds a + b − c.
template <class S>
inline uint32_t MedianPredictor(uint32_t a, uint32_t b, uint32_t c) {
  const S sa = S(a), sb = S(b);
  return uint32_t(std::max(std::min(sa, sb), std::min(std::max(sa, sb), S(sa + sb - S(c)))));
}

// Residual r (width-bit two's complement) ⇄ zigzag code: small magnitudes to small codes.
inline uint32_t ZigZag(uint32_t r, int width, uint32_t mask) {
  return ((r << 1) ^ (0u - (r >> (width - 1)))) & mask;
}
inline uint32_t UnZigZag(uint32_t z, uint32_t mask) {
  return ((z >> 1) ^ (0u - (z & 1u))) & mask;
}

// The mask of a `width`-bit value.
inline uint32_t MaskOf(int width) {
  return width == 32 ? ~0u : (1u << width) - 1;
}

// The prediction of value x of row y (r: its row, up: the row above; `channels` interleaved):
// the median predictor inside, the left neighbour in the first row, the upper one in the first
// column, 0 at the first value.
template <class S>
inline uint32_t PredictionAt(const uint32_t* r, const uint32_t* up, int x, int y, int channels) {
  return x < channels ? (y > 0 ? up[x] : 0u)
         : y == 0     ? r[x - channels]
                      : MedianPredictor<S>(r[x - channels], up[x], up[x - channels]);
}

// The residuals of q (rows × row_values, `channels` interleaved) against their predictions,
// zigzag-coded; `width`-bit values.
template <class S>
void Residuals(const uint32_t* q, int rows, int row_values, int channels, int width,
               uint32_t* codes) {
  const uint32_t mask = MaskOf(width);
  for (int y = 0; y < rows; ++y) {
    const uint32_t* r = q + std::size_t(y) * row_values;
    uint32_t* out = codes + std::size_t(y) * row_values;
    for (int x = 0; x < row_values; ++x) {
      const uint32_t prediction = PredictionAt<S>(r, r - row_values, x, y, channels);
      out[x] = ZigZag((r[x] - prediction) & mask, width, mask);
    }
  }
}

// Inverts Residuals for rows of CH channels: q from the residuals' codes, in order, each
// prediction from values decoded. The left neighbours of a pixel's channels stay in registers
// (each channel is a chain of dependent values; through memory, every step would wait for a
// store to forward).
template <class S, int CH>
void ReconstructPixels(const uint32_t* codes, int rows, int cols, uint32_t mask, uint32_t* q) {
  const std::size_t row_values = std::size_t(cols) * CH;
  for (int y = 0; y < rows; ++y) {
    uint32_t* r = q + std::size_t(y) * row_values;
    const uint32_t* up = r - row_values;
    const uint32_t* in = codes + std::size_t(y) * row_values;
    uint32_t left[CH];
    for (int c = 0; c < CH; ++c)
      left[c] = r[c] = ((y > 0 ? up[c] : 0u) + UnZigZag(in[c], mask)) & mask;
    for (int x = 1; x < cols; ++x) {
      const std::size_t i = std::size_t(x) * CH;
      for (int c = 0; c < CH; ++c) {
        const uint32_t prediction =
            y > 0 ? MedianPredictor<S>(left[c], up[i + c], up[i + c - CH]) : left[c];
        left[c] = r[i + c] = (prediction + UnZigZag(in[i + c], mask)) & mask;
      }
    }
  }
}

template <class S>
void Reconstruct(const uint32_t* codes, int rows, int cols, int channels, int width, uint32_t* q) {
  const uint32_t mask = MaskOf(width);
  switch (channels) {
    case 1:
      return ReconstructPixels<S, 1>(codes, rows, cols, mask, q);
    case 2:
      return ReconstructPixels<S, 2>(codes, rows, cols, mask, q);
    case 3:
      return ReconstructPixels<S, 3>(codes, rows, cols, mask, q);
    case 4:
      return ReconstructPixels<S, 4>(codes, rows, cols, mask, q);
    case 7:
      return ReconstructPixels<S, 7>(codes, rows, cols, mask, q);
    default:
      break;
  }
  const int row_values = cols * channels;  // other channel counts, through memory
  for (int y = 0; y < rows; ++y) {
    uint32_t* r = q + std::size_t(y) * row_values;
    const uint32_t* in = codes + std::size_t(y) * row_values;
    for (int x = 0; x < row_values; ++x)
      r[x] = (PredictionAt<S>(r, r - row_values, x, y, channels) + UnZigZag(in[x], mask)) & mask;
  }
}

// Per thread, what coding reuses: zstd's contexts and the intermediate buffers. Fresh ones for
// every plane cost as much as the compression itself (page faults on megabytes of new memory),
// and a view's planes are coded on several threads at once.
struct Workspace {
  std::unique_ptr<ZSTD_CCtx, std::size_t (*)(ZSTD_CCtx*)> compress{ZSTD_createCCtx(),
                                                                   ZSTD_freeCCtx};
  std::unique_ptr<ZSTD_DCtx, std::size_t (*)(ZSTD_DCtx*)> decompress{ZSTD_createDCtx(),
                                                                     ZSTD_freeDCtx};
  std::vector<uint32_t> values, codes;
  std::vector<uint8_t> bytes, compressed;
};

Workspace& ThreadWorkspace() {
  thread_local Workspace workspace;
  return workspace;
}

// zstd of `raw`, with its checksum, after `header` bytes (the first of which is `drop`).
std::vector<uint8_t> Compress(const std::vector<uint8_t>& raw, int level, std::size_t header,
                              uint8_t drop) {
  Workspace& w = ThreadWorkspace();
  ZSTD_CCtx_reset(w.compress.get(), ZSTD_reset_session_and_parameters);
  ZSTD_CCtx_setParameter(w.compress.get(), ZSTD_c_compressionLevel, level);
  ZSTD_CCtx_setParameter(w.compress.get(), ZSTD_c_checksumFlag, 1);
  w.compressed.resize(ZSTD_compressBound(raw.size()));
  const std::size_t size = ZSTD_compress2(w.compress.get(), w.compressed.data(),
                                          w.compressed.size(), raw.data(), raw.size());
  if (ZSTD_isError(size)) throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(size));
  std::vector<uint8_t> out(header + size);
  if (header > 0) out[0] = drop;
  std::memcpy(out.data() + header, w.compressed.data(), size);
  return out;
}

// The `expected` bytes that `bytes` compress, in the thread's workspace.
const std::vector<uint8_t>& Decompress(const uint8_t* bytes, std::size_t size,
                                       std::size_t expected) {
  if (bytes == nullptr || ZSTD_getFrameContentSize(bytes, size) != expected)
    throw std::runtime_error("compressed plane is corrupt or of another size");
  Workspace& w = ThreadWorkspace();
  w.bytes.resize(expected);
  const std::size_t got =
      ZSTD_decompressDCtx(w.decompress.get(), w.bytes.data(), w.bytes.size(), bytes, size);
  if (ZSTD_isError(got) || got != expected) throw std::runtime_error("compressed plane is corrupt");
  return w.bytes;
}

// Byte b of each of the n values of `element` bytes together: runs of similar bytes.
std::vector<uint8_t> Shuffle(const uint8_t* values, std::size_t n, std::size_t element) {
  std::vector<uint8_t> out(n * element);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t b = 0; b < element; ++b) out[b * n + i] = values[i * element + b];
  return out;
}

std::vector<uint8_t> EncodePredicted(const cv::Mat& m, int drop, int level) {
  const int width = int(8 * m.elemSize1()) - drop;
  Workspace& w = ThreadWorkspace();
  std::vector<uint32_t>& q = w.values;
  std::vector<uint32_t>& codes = w.codes;
  Quantize(m, drop, q);
  const std::size_t n = q.size(), bytes = std::size_t(width + 7) / 8;
  codes.resize(n);
  // a + b − c of width-bit values fits 32 signed bits below 31 bits (floats keep ≤ 23 + 9).
  (width <= 30 ? Residuals<int32_t> : Residuals<int64_t>)(q.data(), m.rows, m.cols * m.channels(),
                                                          m.channels(), width, codes.data());
  std::vector<uint8_t> grouped(n * bytes);  // not w.bytes: Compress may use the workspace
  for (std::size_t b = 0; b < bytes; ++b) {
    uint8_t* out = grouped.data() + b * n;
    for (std::size_t i = 0; i < n; ++i) out[i] = uint8_t(codes[i] >> (8 * b));
  }
  return Compress(grouped, level, 1, uint8_t(drop));
}

cv::Mat DecodePredicted(const uint8_t* bytes, std::size_t size, int rows, int cols, int type) {
  cv::Mat m(rows, cols, type);
  const int element_bits = int(8 * m.elemSize1());
  const bool floats = m.depth() == CV_32F || m.depth() == CV_16F;
  if (size < 1 || bytes[0] >= element_bits || (!floats && bytes[0] != 0))
    throw std::runtime_error("compressed plane is corrupt (bit count)");
  const int drop = bytes[0], width = element_bits - drop;
  const std::size_t n = m.total() * m.channels(), group = std::size_t(width + 7) / 8;
  const std::vector<uint8_t>& grouped = Decompress(bytes + 1, size - 1, n * group);
  Workspace& w = ThreadWorkspace();
  std::vector<uint32_t>& codes = w.codes;
  std::vector<uint32_t>& q = w.values;
  codes.resize(n);
  q.resize(n);
  for (std::size_t i = 0; i < n; ++i) codes[i] = grouped[i];
  for (std::size_t b = 1; b < group; ++b) {
    const uint8_t* in = grouped.data() + b * n;
    for (std::size_t i = 0; i < n; ++i) codes[i] |= uint32_t(in[i]) << (8 * b);
  }
  (width <= 30 ? Reconstruct<int32_t> : Reconstruct<int64_t>)(codes.data(), rows, cols,
                                                              m.channels(), width, q.data());
  if (element_bits == 32) {
    auto* out = reinterpret_cast<uint32_t*>(m.data);
    for (std::size_t i = 0; i < n; ++i) out[i] = q[i] << drop;
  } else if (element_bits == 16) {
    auto* out = reinterpret_cast<uint16_t*>(m.data);
    for (std::size_t i = 0; i < n; ++i) out[i] = uint16_t(q[i] << drop);
  } else {
    for (std::size_t i = 0; i < n; ++i) m.data[i] = uint8_t(q[i]);
  }
  return m;
}

std::vector<uint8_t> EncodeShuffled(const cv::Mat& plane, int drop, int level) {
  const cv::Mat m = plane.clone();  // rounded in place
  const std::size_t n = m.total() * m.channels();
  if (m.depth() == CV_32F) {
    auto* v = reinterpret_cast<uint32_t*>(m.data);
    for (std::size_t i = 0; i < n; ++i) v[i] = RoundBits<uint32_t>(v[i], 0x7F800000u, drop);
  } else if (m.depth() == CV_16F) {
    auto* v = reinterpret_cast<uint16_t*>(m.data);
    for (std::size_t i = 0; i < n; ++i) v[i] = RoundBits<uint16_t>(v[i], 0x7C00u, drop);
  }
  return Compress(Shuffle(m.data, n, m.elemSize1()), level, 0, 0);
}

cv::Mat DecodeShuffled(const uint8_t* bytes, std::size_t size, int rows, int cols, int type) {
  cv::Mat m(rows, cols, type);
  const std::size_t element = m.elemSize1(), n = m.total() * m.channels();
  const std::vector<uint8_t>& shuffled = Decompress(bytes, size, n * element);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t b = 0; b < element; ++b) m.data[i * element + b] = shuffled[b * n + i];
  return m;
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
  if (plane.elemSize1() > 4)
    throw std::invalid_argument("EncodePlane: 64-bit elements are not supported");
  const int drop = DroppedBits(plane.depth(), options);
  const cv::Mat m = plane.isContinuous() ? plane : plane.clone();
  return options.encoding == PlaneEncoding::kShuffled
             ? EncodeShuffled(m, drop, options.zstd_level)
             : EncodePredicted(m, drop, options.zstd_level);
}

cv::Mat DecodePlane(const uint8_t* bytes, std::size_t size, int rows, int cols, int type,
                    PlaneEncoding encoding) {
  if (CV_ELEM_SIZE1(type) > 4) throw std::runtime_error("compressed plane of 64-bit elements");
  return encoding == PlaneEncoding::kShuffled ? DecodeShuffled(bytes, size, rows, cols, type)
                                              : DecodePredicted(bytes, size, rows, cols, type);
}

}  // namespace novelty::views
