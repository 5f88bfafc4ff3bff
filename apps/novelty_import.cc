// novelty-import: a recorded RGB-D sequence, or a fixed camera's folder of images, into an MRPT
// rawlog the maps read (sensors/dataset/rgbd_sequence.h, rgbd_importer.h, fixed_camera_folder.h).
//
//   novelty-import DIR --out OUT.rawlog [--layout auto|tum|icl-nuim|7scenes|fixed-camera|cdnet]
//       [--camera fr1|fr2|fr3|icl-nuim|7scenes | --camera-file FILE | --fx FX --fy FY --cx CX
//        --cy CY]
//       [--depth-scale S] [--max-time-difference 0.02] [--first N] [--last N] [--every K]
//       [--max-pixels N] [--poses auto|dataset|visual] [--include GLOB ...] [--exclude GLOB ...]
//
// DIR is a TUM RGB-D sequence (rgb.txt, depth.txt, groundtruth.txt), an ICL-NUIM folder (color/,
// depth/, pose.txt), a 7-Scenes sequence (frame-NNNNNN.{color,depth}.png, .pose.txt), or with
// --layout fixed-camera a folder of images from one camera that does not move (a static camera's
// frames, or the lightings of one viewpoint; mask.png limits the pixels, --include/--exclude pick
// the files), or with --layout cdnet a CDnet-layout folder (input/in000001.jpg…, ROI.bmp as the
// mask) as a fixed camera. OUT gets one CObservation3DRangeScan per frame with external images in
// OUT_Images/, and a CObservationRobotPose "POSE_DATASET" before each frame the dataset gives a
// pose for (a fixed camera: the origin, its depth a plane), or "POSE_VO" from visual odometry
// (sensors/localization/rgbd_odometry.h) for a sequence without poses or with --poses visual:
// `novelty-run --rawlog OUT` plays it,
// `novelty-illumination-map --lighting OUT:each` learns a lighting per frame, rawlog-edit and
// RawLogViewer open it. Nothing is written when the import fails.
#include <tclap/CmdLine.h>

#include <algorithm>
#include <cmath>
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
#include "sensors/dataset/fixed_camera_folder.h"
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

// The command line, one member a flag.
struct Flags {
  explicit Flags(TCLAP::CmdLine& cmd)
      : in("folder", "The sequence's folder", true, "", "DIR", cmd),
        out("o", "out", "Output rawlog", true, "", "OUT.rawlog", cmd),
        layout("", "layout", "auto, tum, icl-nuim, 7scenes, fixed-camera or cdnet", false,
               sensors::RgbdSequenceOptions().layout, "NAME", cmd),
        camera("", "camera",
               "Intrinsics by name: fr1, fr2, fr3 (TUM), icl-nuim, 7scenes (default: the "
               "layout's, or TUM's from the folder name)",
               false, "", "NAME", cmd),
        camera_file("", "camera-file",
                    "Intrinsics from a ROS camera_info YAML (.yaml) or an MRPT camera .ini "
                    "([CAMERA_PARAMS]); no distortion",
                    false, "", "FILE", cmd),
        fx("", "fx", "Focal length x (px); with --fy --cx --cy", false, 0, "FX", cmd),
        fy("", "fy", "Focal length y (px, negative if y points up)", false, 0, "FY", cmd),
        cx("", "cx", "Principal point x (px)", false, 0, "CX", cmd),
        cy("", "cy", "Principal point y (px)", false, 0, "CY", cmd),
        scale("", "depth-scale",
              "Depth image units per metre (default: the layout's, 5000 TUM and ICL-NUIM, 1000 "
              "7-Scenes)",
              false, 0, "S", cmd),
        max_dt("", "max-time-difference",
               "TUM: seconds between associated colour, depth and pose lines", false,
               sensors::RgbdSequenceOptions().max_time_difference, "SECONDS", cmd),
        first("", "first", "First frame (1-based)", false, 1, "N", cmd),
        last("", "last", "Last frame (0: to the end)", false, 0, "N", cmd),
        every("", "every", "Every K-th frame", false, 1, "K", cmd),
        max_pixels("", "max-pixels", "Largest image accepted (pixels, read from the header)", false,
                   sensors::RgbdImportOptions().max_pixels, "N", cmd),
        poses("", "poses",
              "auto (the dataset's; visual odometry for a sequence without any), dataset or "
              "visual (OpenCV's RGB-D odometry)",
              false, "auto", "SOURCE", cmd),
        include("", "include", "fixed-camera: only images matching GLOB", false, "GLOB", cmd),
        exclude("", "exclude", "fixed-camera: not images matching GLOB", false, "GLOB", cmd) {}
  TCLAP::UnlabeledValueArg<std::string> in;
  TCLAP::ValueArg<std::string> out, layout, camera, camera_file;
  TCLAP::ValueArg<double> fx, fy, cx, cy, scale, max_dt;
  TCLAP::ValueArg<int> first, last, every;
  TCLAP::ValueArg<long long> max_pixels;
  TCLAP::ValueArg<std::string> poses;
  TCLAP::MultiArg<std::string> include, exclude;
};

bool IsFixedCamera(const std::string& layout) {
  return layout == "fixed-camera" || layout == "cdnet";
}

// Every flag is checked before anything is read: a bad value is a usage error naming it.
void CheckFlags(const Flags& f) {
  CheckFlag(f.every.getValue() >= 1, "--every must be >= 1");
  CheckFlag(f.first.getValue() >= 1, "--first must be >= 1");
  CheckFlag(f.last.getValue() == 0 || f.last.getValue() >= f.first.getValue(),
            "--last must be 0 (to the end) or >= --first");
  CheckFlag(f.max_pixels.getValue() >= 1, "--max-pixels must be >= 1");
  CheckFlag(f.max_dt.getValue() >= 0 && f.max_dt.getValue() <= 1,
            "--max-time-difference must be in [0, 1] s");
  CheckFlag(!f.scale.isSet() || (f.scale.getValue() >= 1 && f.scale.getValue() <= 1e6),
            "--depth-scale must be in [1, 1e6] units per metre");
  const std::string l = f.layout.getValue();
  CheckFlag(l == "auto" || l == "tum" || l == "icl-nuim" || l == "7scenes" || l == "fixed-camera" ||
                l == "cdnet",
            "--layout must be auto, tum, icl-nuim, 7scenes, fixed-camera or cdnet");
  const bool fixed = IsFixedCamera(l);
  const std::string p = f.poses.getValue();
  CheckFlag(p == "auto" || p == "dataset" || p == "visual",
            "--poses must be auto, dataset or visual");
  CheckFlag(!fixed || !f.poses.isSet(), "a fixed camera stays at the origin: no --poses");
  CheckFlag(l == "fixed-camera" || !(f.include.isSet() || f.exclude.isSet()),
            "--include and --exclude pick the images of --layout fixed-camera");
  CheckFlag(
      !fixed || !(f.camera.isSet() || f.camera_file.isSet() || f.fx.isSet() || f.scale.isSet()),
      "a fixed camera's intrinsics are nominal and its depth a plane: no --camera, "
      "--camera-file, --fx or --depth-scale");
}

// --layout fixed-camera or cdnet: the folder's images at one pose, a plane as depth.
void ImportFixedCamera(const Flags& f, const sensors::RgbdImportOptions& io) {
  sensors::FixedCameraOptions fo;
  fo.pick = {f.include.getValue(), f.exclude.getValue()};
  fo.max_pixels = io.max_pixels;
  if (f.layout.getValue() == "fixed-camera" &&
      std::filesystem::is_directory(std::filesystem::path(f.in.getValue()) / "input"))
    throw std::runtime_error(f.in.getValue() + ": a CDnet folder (input/): use --layout cdnet");
  const sensors::FixedCameraFolder folder = f.layout.getValue() == "cdnet"
                                                ? sensors::CdnetFixedCamera(f.in.getValue(), fo)
                                                : sensors::FixedCameraFolder(f.in.getValue(), fo);
  const sensors::RgbdImportResult r =
      sensors::ImportFixedCameraFolder(folder, f.out.getValue(), io);
  std::printf("%s: %d images of one fixed camera (%dx%d, %zu left out by the patterns%s) → %s\n",
              f.in.getValue().c_str(), r.frames, folder.camera().width, folder.camera().height,
              folder.listing().left_out.size(), folder.listing().mask.empty() ? "" : ", masked",
              f.out.getValue().c_str());
}

// The RGB-D layouts.
void ImportSequence(const Flags& f, const sensors::RgbdImportOptions& io) {
  sensors::RgbdSequenceOptions o;
  o.layout = f.layout.getValue();
  o.max_time_difference = f.max_dt.getValue();
  o.depth_scale = f.scale.getValue();
  SetCamera(f.camera, f.camera_file, {&f.fx, &f.fy, &f.cx, &f.cy}, o);
  const sensors::RgbdSequence s = sensors::ReadRgbdSequence(f.in.getValue(), o);
  if (f.camera_file.isSet() &&
      (s.camera.width != o.camera->width || s.camera.height != o.camera->height))
    throw std::runtime_error(
        f.camera_file.getValue() + ": calibrated at " + std::to_string(o.camera->width) + "x" +
        std::to_string(o.camera->height) + ", the images are " + std::to_string(s.camera.width) +
        "x" + std::to_string(s.camera.height));
  const sensors::RgbdImportResult r = sensors::ImportRgbdSequence(s, f.out.getValue(), io);
  std::printf(
      "%s: %zu frames (%s layout, %dx%d, fx %.1f from %s), %d colour images without depth, %d "
      "frames without a pose\n%d RGB-D frames, %d with a pose, depth known at %.1f %% of the "
      "pixels (%lld beyond the rawlog's %.1f m, stored as unknown) → %s\n",
      f.in.getValue().c_str(), s.frames.size(), s.layout.c_str(), s.camera.width, s.camera.height,
      s.camera.fx, s.camera_source.c_str(), s.unmatched_rgb, s.unposed, r.frames, r.posed,
      100 * r.depth_coverage, r.beyond_range, double(sensors::kRgbdMaxDepth),
      f.out.getValue().c_str());
  if (r.visual_odometry)
    std::printf("poses from visual odometry (POSE_VO): %d frames placed, %d lost%s\n", r.posed,
                r.odometry_lost,
                std::isnan(r.odometry_rms_error)
                    ? ""
                    : (", " + std::to_string(int(std::lround(1000 * r.odometry_rms_error))) +
                       " mm RMS from the dataset's")
                          .c_str());
}

int Run(int argc, char** argv) {
  apps::CommandLine cmd(
      "Imports a recorded RGB-D sequence (TUM RGB-D, ICL-NUIM, 7-Scenes) or a fixed camera's "
      "images into an MRPT rawlog",
      "0.1");
  const Flags f(cmd);
  cmd.Parse(argc, argv);
  CheckFlags(f);
  if (!IsFixedCamera(f.layout.getValue())) {  // the camera flags' combinations
    sensors::RgbdSequenceOptions probe;
    SetCamera(f.camera, f.camera_file, {&f.fx, &f.fy, &f.cx, &f.cy}, probe);
  }
  CheckOutput(f.out.getValue(), f.in.getValue());
  sensors::RgbdImportOptions io;
  io.first = f.first.getValue(), io.last = f.last.getValue(), io.every = f.every.getValue();
  io.max_pixels = f.max_pixels.getValue();
  io.poses = f.poses.getValue() == "visual"    ? sensors::ImportPoses::kVisual
             : f.poses.getValue() == "dataset" ? sensors::ImportPoses::kDataset
                                               : sensors::ImportPoses::kAuto;
  std::optional<apps::Progress> progress;
  io.progress = [&](int done, int total) {
    if (!progress) progress.emplace("[novelty-import] frames", total);
    progress->Update(done);
    if (done == total) progress->Finish();
  };
  if (IsFixedCamera(f.layout.getValue()))
    ImportFixedCamera(f, io);
  else
    ImportSequence(f, io);
  return apps::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-import", [&] { return Run(argc, argv); });
}
