// novelty-import: a recorded RGB-D sequence into an MRPT rawlog the maps read
// (sensors/dataset/rgbd_sequence.h, rgbd_importer.h).
//
//   novelty-import DIR --out OUT.rawlog [--layout auto|tum|icl-nuim|7scenes]
//       [--camera fr1|fr2|fr3|icl-nuim|7scenes | --camera-file FILE | --fx FX --fy FY --cx CX
//        --cy CY]
//       [--depth-scale S] [--max-time-difference 0.02] [--first N] [--last N] [--every K]
//       [--max-pixels N]
//
// DIR is a TUM RGB-D sequence (rgb.txt, depth.txt, groundtruth.txt), an ICL-NUIM folder (color/,
// depth/, pose.txt) or a 7-Scenes sequence (frame-NNNNNN.{color,depth}.png, .pose.txt). OUT gets
// one CObservation3DRangeScan per frame with external images in OUT_Images/, and a
// CObservationRobotPose "POSE_DATASET" before each frame the dataset gives a pose for:
// `novelty-run --rawlog OUT --poses rawlog` plays it, rawlog-edit and RawLogViewer open it.
// Nothing is written when the import fails.
#include <tclap/CmdLine.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "apps/command_line.h"
#include "apps/shell/output_folder.h"
#include "apps/shell/program.h"
#include "apps/shell/progress.h"
#include "sensors/dataset/camera_file.h"
#include "sensors/dataset/rgbd_importer.h"
#include "sensors/rawlog/rawlog_input.h"
#include "sensors/rawlog/rgbd_observation.h"

using namespace novelty;

namespace {

void CheckFlag(bool ok, const std::string& message) {
  if (!ok) throw apps::UsageError(message);
}

// The intrinsics from one of --camera, --camera-file or --fx --fy --cx --cy (or the layout's).
void SetCamera(const TCLAP::ValueArg<std::string>& name, const TCLAP::ValueArg<std::string>& file,
               const std::vector<const TCLAP::ValueArg<double>*>& k,
               sensors::RgbdSequenceOptions& o) {
  int given = 0;
  for (const auto* a : k) given += a->isSet();
  CheckFlag(given == 0 || given == 4, "give all of --fx --fy --cx --cy, or none");
  CheckFlag(given / 4 + name.isSet() + file.isSet() <= 1,
            "give the intrinsics once: --camera, --camera-file or --fx --fy --cx --cy");
  o.camera_name = name.getValue();
  if (name.isSet()) {
    try {
      sensors::NamedCamera(name.getValue());
    } catch (const std::invalid_argument& e) {
      throw apps::UsageError(std::string("--camera ") + e.what());
    }
  }
  if (given == 4) {
    core::PinholeCamera c;
    c.fx = k[0]->getValue(), c.fy = k[1]->getValue(), c.cx = k[2]->getValue();
    c.cy = k[3]->getValue();
    o.camera = c;
    o.camera_source = "--fx --fy --cx --cy";
  }
  if (file.isSet()) {
    o.camera = sensors::ReadCameraFile(file.getValue());
    o.camera_source = file.getValue();
  }
  if (o.camera && o.camera_name.empty()) o.camera_name = "fr1";  // replaced by the given ones
}

// OUT may replace an earlier rawlog only; its images folder must not be, hold or lie in the
// input (a sequence folder named like OUT_Images would be written into).
void CheckOutput(const std::string& out, const std::string& in) {
  apps::CheckOutputFile("--out", out, {in}, [](const std::string& p) {
    try {
      return sensors::RawlogInput(p).Next() != nullptr;
    } catch (const std::exception&) {
      return false;
    }
  });
  namespace fs = std::filesystem;
  const auto canonical = [](const std::string& p) {  // "DIR/" as "DIR": no empty last part
    const fs::path c = fs::weakly_canonical(p);
    return c.filename().empty() ? c.parent_path() : c;
  };
  const fs::path images = canonical(sensors::ImagesDirOf(out)), input = canonical(in);
  const auto within = [](const fs::path& inner, const fs::path& outer) {
    const auto [end, _] = std::mismatch(outer.begin(), outer.end(), inner.begin(), inner.end());
    return end == outer.end();
  };
  if (within(images, input) || within(input, images))
    throw std::runtime_error("--out " + out + ": its images folder " + images.string() +
                             " would be written into the input " + in);
}

int Run(int argc, char** argv) {
  apps::CommandLine cmd(
      "Imports a recorded RGB-D sequence (TUM RGB-D, ICL-NUIM, 7-Scenes) into "
      "an MRPT rawlog",
      "0.1");
  TCLAP::UnlabeledValueArg<std::string> in("folder", "The sequence's folder", true, "", "DIR", cmd);
  TCLAP::ValueArg<std::string> out("o", "out", "Output rawlog", true, "", "OUT.rawlog", cmd);
  const sensors::RgbdSequenceOptions defaults;
  TCLAP::ValueArg<std::string> layout("", "layout", "auto, tum, icl-nuim or 7scenes", false,
                                      defaults.layout, "NAME", cmd);
  TCLAP::ValueArg<std::string> camera(
      "", "camera",
      "Intrinsics by name: fr1, fr2, fr3 (TUM), icl-nuim, 7scenes (default: the layout's, or "
      "TUM's from the folder name)",
      false, "", "NAME", cmd);
  TCLAP::ValueArg<std::string> camera_file(
      "", "camera-file",
      "Intrinsics from a ROS camera_info YAML (.yaml) or an MRPT camera .ini ([CAMERA_PARAMS]); "
      "no distortion",
      false, "", "FILE", cmd);
  TCLAP::ValueArg<double> fx("", "fx", "Focal length x (px); with --fy --cx --cy", false, 0, "FX",
                             cmd);
  TCLAP::ValueArg<double> fy("", "fy", "Focal length y (px, negative if y points up)", false, 0,
                             "FY", cmd);
  TCLAP::ValueArg<double> cx("", "cx", "Principal point x (px)", false, 0, "CX", cmd);
  TCLAP::ValueArg<double> cy("", "cy", "Principal point y (px)", false, 0, "CY", cmd);
  TCLAP::ValueArg<double> scale("", "depth-scale",
                                "Depth image units per metre (default: the layout's, 5000 TUM "
                                "and ICL-NUIM, 1000 7-Scenes)",
                                false, 0, "S", cmd);
  TCLAP::ValueArg<double> max_dt("", "max-time-difference",
                                 "TUM: seconds between associated colour, depth and pose lines",
                                 false, defaults.max_time_difference, "SECONDS", cmd);
  const sensors::RgbdImportOptions import_defaults;
  TCLAP::ValueArg<int> first("", "first", "First frame (1-based)", false, 1, "N", cmd);
  TCLAP::ValueArg<int> last("", "last", "Last frame (0: to the end)", false, 0, "N", cmd);
  TCLAP::ValueArg<int> every("", "every", "Every K-th frame", false, 1, "K", cmd);
  TCLAP::ValueArg<long long> max_pixels("", "max-pixels",
                                        "Largest image accepted (pixels, read from the header)",
                                        false, import_defaults.max_pixels, "N", cmd);
  cmd.Parse(argc, argv);
  // Every flag is checked before anything is read: a bad value is a usage error naming it.
  CheckFlag(every.getValue() >= 1, "--every must be >= 1");
  CheckFlag(first.getValue() >= 1, "--first must be >= 1");
  CheckFlag(last.getValue() == 0 || last.getValue() >= first.getValue(),
            "--last must be 0 (to the end) or >= --first");
  CheckFlag(max_pixels.getValue() >= 1, "--max-pixels must be >= 1");
  CheckFlag(max_dt.getValue() >= 0 && max_dt.getValue() <= 1,
            "--max-time-difference must be in [0, 1] s");
  CheckFlag(!scale.isSet() || (scale.getValue() >= 1 && scale.getValue() <= 1e6),
            "--depth-scale must be in [1, 1e6] units per metre");
  CheckFlag(layout.getValue() == "auto" || layout.getValue() == "tum" ||
                layout.getValue() == "icl-nuim" || layout.getValue() == "7scenes",
            "--layout must be auto, tum, icl-nuim or 7scenes");
  sensors::RgbdSequenceOptions o;
  o.layout = layout.getValue();
  o.max_time_difference = max_dt.getValue();
  o.depth_scale = scale.getValue();
  SetCamera(camera, camera_file, {&fx, &fy, &cx, &cy}, o);
  CheckOutput(out.getValue(), in.getValue());

  const sensors::RgbdSequence s = sensors::ReadRgbdSequence(in.getValue(), o);
  if (camera_file.isSet() &&
      (s.camera.width != o.camera->width || s.camera.height != o.camera->height))
    throw std::runtime_error(
        camera_file.getValue() + ": calibrated at " + std::to_string(o.camera->width) + "x" +
        std::to_string(o.camera->height) + ", the images are " + std::to_string(s.camera.width) +
        "x" + std::to_string(s.camera.height));
  sensors::RgbdImportOptions io;
  io.first = first.getValue(), io.last = last.getValue(), io.every = every.getValue();
  io.max_pixels = max_pixels.getValue();
  std::optional<apps::Progress> progress;
  io.progress = [&](int done, int total) {
    if (!progress) progress.emplace("[novelty-import] frames", total);
    progress->Update(done);
  };
  const sensors::RgbdImportResult r = sensors::ImportRgbdSequence(s, out.getValue(), io);
  if (progress) progress->Finish();
  std::printf(
      "%s: %zu frames (%s layout, %dx%d, fx %.1f from %s), %d colour images without depth, %d "
      "frames without a pose\n%d RGB-D frames, %d with a pose, depth known at %.1f %% of the "
      "pixels (%lld beyond the rawlog's %.1f m, stored as unknown) → %s\n",
      in.getValue().c_str(), s.frames.size(), s.layout.c_str(), s.camera.width, s.camera.height,
      s.camera.fx, s.camera_source.c_str(), s.unmatched_rgb, s.unposed, r.frames, r.posed,
      100 * r.depth_coverage, r.beyond_range, double(sensors::kRgbdMaxDepth),
      out.getValue().c_str());
  return apps::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-import", [&] { return Run(argc, argv); });
}
