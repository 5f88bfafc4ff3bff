#include "sensors/rawlog/rawlog_input.h"

#include <gtest/gtest.h>
#include <mrpt/obs/CObservation3DRangeScan.h>

#include <filesystem>

#include "tests/sensors/rawlog/tiny_run.h"

namespace novelty::sensors {
namespace {

namespace fs = std::filesystem;

TEST(ImagesDirOf, IsTheRawlogsNameWithImagesBesideIt) {
  EXPECT_EQ(ImagesDirOf("/data/runs/glass.rawlog"), "/data/runs/glass_Images");
  EXPECT_EQ(ImagesDirOf("runs/a.b.rawlog"), "runs/a.b_Images");
  EXPECT_EQ(ImagesDirOf("glass.rawlog"), "glass_Images");
}

// A rawlog opened from another folder than the working one: its external images load (MRPT's
// own lookup would search beside the working folder).
TEST(RawlogInput, FindsExternalImagesFromAnyWorkingFolder) {
  const fs::path dir = SimulateTinyRun("input");
  const fs::path cwd = fs::current_path();
  fs::current_path(fs::temp_directory_path());
  RawlogInput input((dir / "tiny.rawlog").string());
  int images = 0;
  while (const auto object = input.Next()) {
    if (auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation3DRangeScan>(object)) {
      scan->load();  // external images resolved against tiny_Images/
      ASSERT_EQ(scan->intensityImage.getWidth(), 64u) << "object " << input.object();
      ++images;
    }
  }
  fs::current_path(cwd);
  EXPECT_EQ(images, 6);
  EXPECT_THROW(RawlogInput((dir / "missing.rawlog").string()), std::runtime_error);
}

}  // namespace
}  // namespace novelty::sensors
