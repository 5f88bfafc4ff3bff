#include "sensors/dataset/image_header.h"

#include <array>
#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "core/regular_file.h"

namespace novelty::sensors {
namespace {

[[noreturn]] void Fail(const std::string& path, const std::string& why) {
  throw std::runtime_error(path + ": " + why);
}

uint32_t BigEndian(const unsigned char* p, int bytes) {
  uint32_t v = 0;
  for (int i = 0; i < bytes; ++i) v = (v << 8) | p[i];
  return v;
}

uint32_t LittleEndian(const unsigned char* p, int bytes) {
  uint32_t v = 0;
  for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}

// PNG: the signature, then IHDR: width, height (big-endian), bit depth, colour type.
ImageHeader Png(const std::string& path, const std::vector<unsigned char>& h) {
  if (h.size() < 26 || std::string(h.begin() + 12, h.begin() + 16) != "IHDR")
    Fail(path, "PNG header cut short");
  ImageHeader r;
  r.size = cv::Size(int(BigEndian(&h[16], 4)), int(BigEndian(&h[20], 4)));
  r.bit_depth = h[24] == 16 ? 16 : 8;
  static const std::array<int, 7> channels = {1, 0, 3, 1, 2, 0, 4};  // by colour type 0…6
  r.channels = h[25] < channels.size() ? channels[h[25]] : 0;
  if (h[25] == 3) r.bit_depth = 8;  // palette: expands to 8-bit RGB
  if (r.channels == 0) Fail(path, "PNG colour type " + std::to_string(h[25]) + " is not valid");
  return r;
}

// JPEG: markers after SOI until a start-of-frame (SOF0…SOF15 but DHT, JPG and DAC).
ImageHeader Jpeg(const std::string& path, std::ifstream& in) {
  in.seekg(2);
  unsigned char m[4];
  while (in.read(reinterpret_cast<char*>(m), 4)) {
    if (m[0] != 0xFF) Fail(path, "JPEG marker expected");
    const int marker = m[1];
    const uint32_t length = BigEndian(&m[2], 2);
    if (length < 2) Fail(path, "JPEG segment length " + std::to_string(length));
    const bool sof =
        marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (sof) {
      unsigned char f[6];
      if (!in.read(reinterpret_cast<char*>(f), 6)) break;
      ImageHeader r;
      r.bit_depth = f[0] > 8 ? 16 : 8;
      r.size = cv::Size(int(BigEndian(&f[3], 2)), int(BigEndian(&f[1], 2)));
      r.channels = f[5] == 1 ? 1 : 3;
      return r;
    }
    in.seekg(length - 2, std::ios::cur);
  }
  Fail(path, "JPEG without a frame header (cut short?)");
}

// BMP: BITMAPINFOHEADER's width and (signed: bottom-up or top-down) height, bits per pixel.
ImageHeader Bmp(const std::string& path, const std::vector<unsigned char>& h) {
  if (h.size() < 30) Fail(path, "BMP header cut short");
  ImageHeader r;
  const int32_t height = int32_t(LittleEndian(&h[22], 4));
  r.size = cv::Size(int(int32_t(LittleEndian(&h[18], 4))), height < 0 ? -height : height);
  const int bits = int(LittleEndian(&h[28], 2));
  r.channels = bits <= 8 ? 1 : bits == 32 ? 4 : 3;
  r.bit_depth = 8;
  return r;
}

// The file's last `n` bytes (fewer if it is shorter).
std::vector<unsigned char> Tail(std::ifstream& in, std::size_t n) {
  in.clear();
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  const std::streamoff from = size > std::streamoff(n) ? size - std::streamoff(n) : 0;
  std::vector<unsigned char> t(std::size_t(size - from));
  in.seekg(from);
  in.read(reinterpret_cast<char*>(t.data()), std::streamsize(t.size()));
  return t;
}

// A file cut short decodes without an error in OpenCV (the rest grey, a libjpeg warning): its
// end is checked — PNG's IEND chunk, JPEG's EOI marker (trailing zero padding allowed), BMP's
// size as its header states it.
void CheckComplete(const std::string& path, std::ifstream& in, const std::vector<unsigned char>& h,
                   char format) {
  if (format == 'P') {
    const std::vector<unsigned char> t = Tail(in, 12);
    if (t.size() < 12 || std::string(t.begin() + 4, t.begin() + 8) != "IEND")
      Fail(path, "PNG cut short (no IEND chunk at its end)");
  } else if (format == 'J') {
    std::vector<unsigned char> t = Tail(in, 4096);
    while (!t.empty() && t.back() == 0) t.pop_back();
    if (t.size() < 2 || t[t.size() - 2] != 0xFF || t.back() != 0xD9)
      Fail(path, "JPEG cut short (no end-of-image marker)");
  } else if (format == 'B') {
    in.clear();
    in.seekg(0, std::ios::end);
    if (std::uint64_t(in.tellg()) < LittleEndian(&h[2], 4))
      Fail(path, "BMP cut short (smaller than its header says)");
  }
}

}  // namespace

ImageHeader ReadImageHeader(const std::string& path) {
  core::CheckRegularFile(path, std::uintmax_t(1) << 31);
  std::ifstream in(path, std::ios::binary);
  if (!in) Fail(path, "cannot open");
  std::vector<unsigned char> h(32, 0);
  in.read(reinterpret_cast<char*>(h.data()), std::streamsize(h.size()));
  h.resize(std::size_t(in.gcount()));
  in.clear();
  ImageHeader r;
  char format = 0;
  static const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (h.size() >= 8 && std::equal(kPng, kPng + 8, h.begin()))
    r = Png(path, h), format = 'P';
  else if (h.size() >= 3 && h[0] == 0xFF && h[1] == 0xD8 && h[2] == 0xFF)
    r = Jpeg(path, in), format = 'J';
  else if (h.size() >= 2 && h[0] == 'B' && h[1] == 'M')
    r = Bmp(path, h), format = 'B';
  else
    Fail(path, h.empty() ? "empty file" : "not a PNG, JPEG or BMP image");
  CheckComplete(path, in, h, format);
  if (r.size.width <= 0 || r.size.height <= 0)
    Fail(path,
         "image of size " + std::to_string(r.size.width) + "x" + std::to_string(r.size.height));
  return r;
}

ImageHeader CheckImageHeader(const std::string& path, long long max_pixels) {
  const ImageHeader h = ReadImageHeader(path);
  const long long pixels = 1LL * h.size.width * h.size.height;
  if (pixels > max_pixels)
    Fail(path, std::to_string(h.size.width) + "x" + std::to_string(h.size.height) + " = " +
                   std::to_string(pixels) + " pixels, more than the limit of " +
                   std::to_string(max_pixels));
  return h;
}

}  // namespace novelty::sensors
