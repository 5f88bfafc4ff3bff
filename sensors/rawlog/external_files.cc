#include "sensors/rawlog/external_files.h"

#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <zlib.h>

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <vector>

namespace novelty::sensors {

void CheckGzipComplete(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw std::runtime_error(path + ": missing");
  const std::unique_ptr<gzFile_s, int (*)(gzFile)> file(gzopen(path.c_str(), "rb"), gzclose);
  if (!file) throw std::runtime_error(path + ": cannot open");
  char buffer[1 << 14];
  int n = 0;
  while ((n = gzread(file.get(), buffer, sizeof buffer)) > 0) {
  }
  int error = Z_OK;
  gzerror(file.get(), &error);
  if (n < 0 || (error != Z_OK && error != Z_STREAM_END)) {
    throw std::runtime_error(path + ": truncated or corrupt gzip" +
                             (error == Z_BUF_ERROR ? std::string(" (ends early)") : ""));
  }
}

void CheckImageFolder(const mrpt::obs::CObservation& obs, const std::string& where) {
  std::vector<const mrpt::img::CImage*> images;
  if (const auto* scan = dynamic_cast<const mrpt::obs::CObservation3DRangeScan*>(&obs)) {
    images = {&scan->intensityImage};
  } else if (const auto* pair = dynamic_cast<const mrpt::obs::CObservationStereoImages*>(&obs)) {
    images = {&pair->imageLeft, &pair->imageRight};
  }
  for (const mrpt::img::CImage* image : images) {
    if (!image->isExternallyStored()) continue;
    const std::filesystem::path file = image->getExternalStorageFileAbsolutePath();
    if (!std::filesystem::is_directory(file.parent_path())) {
      throw std::runtime_error(where + ": image folder " + file.parent_path().string() +
                               " is missing");
    }
  }
}

void CheckExternalDepth(const mrpt::obs::CObservation& obs) {
  const auto* scan = dynamic_cast<const mrpt::obs::CObservation3DRangeScan*>(&obs);
  if (!scan || !scan->hasRangeImage || !scan->rangeImage_isExternallyStored()) return;
  const std::string path = scan->rangeImage_getExternalStorageFileAbsolutePath("");
  // MRPT writes ".bin" depth matrices gzip-compressed; anything else is left to MRPT.
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw std::runtime_error(path + ": missing");
  unsigned char magic[2] = {0, 0};
  const bool gzip = std::fread(magic, 1, 2, f) == 2 && magic[0] == 0x1f && magic[1] == 0x8b;
  std::fclose(f);
  if (gzip) CheckGzipComplete(path);
}

}  // namespace novelty::sensors
