// Recognising known objects in one's own images or rawlog and listing what was found (issue 51
// item 5; objects::FindObjects per frame): no ground truth. The input is an image, a folder of
// images (any sizes; intrinsics nominal unless given) or an MRPT rawlog of RGB-D observations
// (their intrinsics, depth and, where the rawlog gives one, pose — the place of an object is then
// in world coordinates). Writes into the output folder:
//   found.csv    one row per (frame, object found): verified, matches, inliers, the outline and
//                its box in pixels, the place in the camera and the world (m; empty if unknown)
//   objects.csv  per object name: frames found, frames verified, first and last frame
//   panels/      each frame with something found (up to max_panels), outlines drawn: green
//                verified, orange a candidate
#pragma once

#include <cstdio>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/pinhole_camera.h"
#include "maps/objects/object_finder.h"
#include "sensors/dataset/image_header.h"
#include "sensors/dataset/lighting_folder_reader.h"

namespace novelty::experiments {

struct ObjectFinderRunOptions {
  std::string database;  ///< a CObjectDatabaseMap file (novelty-learn-objects, novelty-run)
  std::string input;     ///< an image, a folder of images or a .rawlog
  sensors::LightingFolderOptions pick;  ///< which files of a folder are frames
  /// Images' intrinsics; none: nominal (focal length the larger side, centred), which scales only
  /// the pose of a verified object, not whether it is found. A rawlog's frames bring their own.
  std::optional<core::PinholeCamera> camera;
  objects::ObjectFinderOptions finder;
  int max_panels = 50;  ///< panels written at most (0: none)
  long long max_pixels = sensors::kDefaultMaxImagePixels;
  std::FILE* console = nullptr;                       ///< one line per object found
  std::function<void(int done, int total)> progress;  ///< total 0 when unknown (a rawlog)
};

struct ObjectSightings {
  int frames = 0, verified = 0, first = 0, last = 0;
};

struct ObjectFinderRunResult {
  int frames = 0;   ///< frames searched
  int skipped = 0;  ///< frames that could not be read (an image, a rawlog frame), skipped
  std::vector<std::string> skip_reasons;  ///< one per skipped frame, naming it
  /// Why the rawlog ended early (truncated or corrupt after its last frame read); empty if not.
  std::string stopped_by;
  std::map<std::string, ObjectSightings> objects;  ///< per name found
};

/// Throws std::runtime_error naming the file: an unreadable database or input, a database
/// without objects, an input without a frame that could be used.
ObjectFinderRunResult RunObjectFinder(const ObjectFinderRunOptions& options,
                                      const std::string& out_dir);

}  // namespace novelty::experiments
