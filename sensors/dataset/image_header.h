// An image file's size and channel layout read from its header, before anything is decoded, so
// that an importer refuses a 20 000 × 20 000 PNG or a frame of another size without allocating
// gigabytes. PNG (IHDR), JPEG (the first SOF marker) and BMP (BITMAPINFOHEADER) are read; other
// formats are refused by name. The file's end is checked too: OpenCV decodes a file cut short
// without an error.
#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace novelty::sensors {

struct ImageHeader {
  cv::Size size;
  int channels = 0;   ///< 1 grey, 3 colour, 4 with alpha (2 grey + alpha)
  int bit_depth = 0;  ///< bits per channel: 8 or 16
};

/// Throws std::runtime_error naming `path` when it is no regular file, cannot be opened, is not
/// one of the formats above, its header is implausible (zero size) or the file is cut short.
ImageHeader ReadImageHeader(const std::string& path);

/// ReadImageHeader, then: at most `max_pixels` pixels, or std::runtime_error naming the file and
/// both numbers.
ImageHeader CheckImageHeader(const std::string& path, long long max_pixels);

/// The default limit of the importers: 4096 × 4096 pixels (64 MB for a 16-bit RGB frame).
inline constexpr long long kDefaultMaxImagePixels = 4096LL * 4096LL;

}  // namespace novelty::sensors
