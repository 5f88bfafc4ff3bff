// libFuzzer target: rawlogs as the programs read them — objects one after another, RGB-D frames
// checked and decoded (sensors/rawlog). MRPT reads plain and gzip'd rawlogs alike; the seeds are
// plain.
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "core/pinhole_camera.h"
#include "sensors/rawlog/external_files.h"
#include "sensors/rawlog/rawlog_input.h"
#include "sensors/rawlog/rgbd_observation.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = "/tmp/novelty_rawlog_fuzz_" + std::to_string(getpid()) + ".rawlog";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  try {
    novelty::sensors::RawlogInput in(path);
    for (int k = 0; k < 64; ++k) {
      const auto object = in.Next();
      if (!object) break;
      const auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation3DRangeScan>(object);
      if (!scan) continue;
      try {
        novelty::sensors::CheckExternalDepth(*scan);
        scan->load();
        cv::Mat rgb, depth;
        novelty::core::PinholeCamera camera;
        novelty::sensors::DecodeRgbd(*scan, rgb, depth, camera);
      } catch (const std::exception&) {  // a frame that cannot be used is skipped
      }
    }
  } catch (const std::runtime_error&) {
  }
  return 0;
}
