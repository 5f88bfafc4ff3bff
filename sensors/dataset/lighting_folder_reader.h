// Reads a folder of images of one viewpoint under different lights, the input of
// novelty-invariant: every image file in it (PNG, JPEG, TIFF, BMP, PNM), in name order, 8 or 16
// bits, colour or grey. Files named mask.*, reflectance.*, shading.* and diffuse.* are not
// lightings: a mask (non-zero = the pixels to use) and, in the MIT Intrinsic Images layout, the
// ground truth of the decomposition (true reflectance and shading, the diffuse image the
// benchmark divides to score a shading estimate). Patterns pick the lightings where a folder
// holds other images too (a depth map, an ambient-only shot).
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace novelty::sensors {

struct LightingFolder {
  std::vector<cv::Mat> images;     ///< R G B (or grey), CV_8U or CV_16U as stored
  std::vector<std::string> names;  ///< their file names
  cv::Mat mask;                    ///< CV_8UC1 (255 = use), empty when the folder has none
  /// Ground truth, float on the 0…255 scale (R G B or grey), each empty when absent.
  cv::Mat reflectance, shading, diffuse;
  std::vector<std::string> left_out;  ///< image files the patterns left out, in name order
};

/// Which image files are lightings: shell patterns (fnmatch: *, ?, [...]) on the file name.
struct LightingFolderOptions {
  std::vector<std::string> include;  ///< a lighting matches one of these; empty: every image
  std::vector<std::string> exclude;  ///< … and none of these, e.g. "*_Ambient*", "depth*"
};

/// A folder's image files by role, paths in name order, nothing decoded.
struct ImageFolderListing {
  std::vector<std::string> images;  ///< what the patterns pick (lightings, or frames to judge)
  std::string mask, reflectance, shading, diffuse;  ///< paths, empty when absent
  std::vector<std::string> left_out;                ///< file names the patterns left out
};

/// Lists `folder` as ReadLightingFolder reads it; throws std::runtime_error naming a folder that
/// does not exist.
ImageFolderListing ListImageFolder(const std::string& folder,
                                   const LightingFolderOptions& options = {});

/// One image file as ReadLightingFolder keeps it (R G B or grey, 8 or 16 bits as stored); throws
/// std::runtime_error naming the file.
cv::Mat ReadFolderImage(const std::string& path);

/// A mask file: CV_8UC1, 255 where it is non-zero (any channel layout read as grey).
cv::Mat ReadFolderMask(const std::string& path);

/// Throws std::runtime_error naming the folder or file: a folder that does not exist, fewer than
/// two lightings (after the patterns; the message names how many they left out) (one image is a
/// single lighting: no invariant image), a file that cannot be read, or images whose size or
/// channels differ from the first one's.
LightingFolder ReadLightingFolder(const std::string& folder,
                                  const LightingFolderOptions& options = {});

}  // namespace novelty::sensors
