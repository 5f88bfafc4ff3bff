#include "sensors/dataset/lighting_folder_reader.h"

#include <fnmatch.h>
#include <algorithm>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <set>
#include <stdexcept>

#include "core/float_image.h"

namespace novelty::sensors {

namespace {

namespace fs = std::filesystem;

std::string Lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

bool IsImage(const fs::path& p) {
  static const std::set<std::string> kExtensions = {".png", ".jpg", ".jpeg", ".tif", ".tiff",
                                                    ".bmp", ".ppm", ".pgm",  ".pnm"};
  return kExtensions.count(Lower(p.extension().string())) > 0;
}

// R G B (or grey) as stored, EXIF orientation ignored (the header's size: every image of one
// camera shares it); throws naming the file.
cv::Mat ReadImage(const fs::path& path) {
  const cv::Mat raw = cv::imread(
      path.string(), cv::IMREAD_ANYDEPTH | cv::IMREAD_ANYCOLOR | cv::IMREAD_IGNORE_ORIENTATION);
  if (raw.empty()) throw std::runtime_error(path.string() + ": cannot be read as an image");
  if (raw.depth() != CV_8U && raw.depth() != CV_16U)
    throw std::runtime_error(path.string() + ": only 8- and 16-bit images are supported");
  cv::Mat out;
  if (raw.channels() == 3)
    cv::cvtColor(raw, out, cv::COLOR_BGR2RGB);
  else if (raw.channels() == 4)
    cv::cvtColor(raw, out, cv::COLOR_BGRA2RGB);
  else
    out = raw;
  return out;
}

bool MatchesAny(const std::vector<std::string>& patterns, const std::string& name) {
  return std::any_of(patterns.begin(), patterns.end(), [&](const std::string& p) {
    return fnmatch(p.c_str(), name.c_str(), 0) == 0;
  });
}

std::string Describe(const cv::Mat& m) {
  return std::to_string(m.cols) + "x" + std::to_string(m.rows) + " with " +
         std::to_string(m.channels()) + " channel(s)";
}

}  // namespace

ImageFolderListing ListImageFolder(const std::string& folder, const LightingFolderOptions& o) {
  if (!fs::is_directory(folder)) throw std::runtime_error(folder + ": no such folder of images");
  ImageFolderListing out;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const fs::path p = entry.path();
    if (!entry.is_regular_file() || !IsImage(p) || p.filename().string().front() == '.') continue;
    const std::string stem = Lower(p.stem().string()), name = p.filename().string();
    if (stem == "mask")
      out.mask = p.string();
    else if (stem == "reflectance")
      out.reflectance = p.string();
    else if (stem == "shading")
      out.shading = p.string();
    else if (stem == "diffuse")
      out.diffuse = p.string();
    else if ((o.include.empty() || MatchesAny(o.include, name)) && !MatchesAny(o.exclude, name))
      out.images.push_back(p.string());
    else
      out.left_out.push_back(name);
  }
  std::sort(out.images.begin(), out.images.end());
  std::sort(out.left_out.begin(), out.left_out.end());
  return out;
}

cv::Mat ReadFolderImage(const std::string& path) {
  return ReadImage(path);
}

cv::Mat ReadFolderMask(const std::string& path) {
  cv::Mat m = ReadImage(path);
  if (m.channels() == 3) cv::cvtColor(m, m, cv::COLOR_RGB2GRAY);
  return m > 0;
}

LightingFolder ReadLightingFolder(const std::string& folder, const LightingFolderOptions& o) {
  if (!fs::is_directory(folder)) throw std::runtime_error(folder + ": no such folder of lightings");
  const ImageFolderListing listing = ListImageFolder(folder, o);
  LightingFolder out;
  out.left_out = listing.left_out;
  if (!listing.mask.empty()) out.mask = ReadFolderMask(listing.mask);
  if (!listing.reflectance.empty())
    out.reflectance = core::ToFloat255(ReadImage(listing.reflectance));
  if (!listing.shading.empty()) out.shading = core::ToFloat255(ReadImage(listing.shading));
  if (!listing.diffuse.empty()) out.diffuse = core::ToFloat255(ReadImage(listing.diffuse));
  const std::vector<fs::path> lightings(listing.images.begin(), listing.images.end());
  if (lightings.size() < 2)
    throw std::runtime_error(
        folder + ": " + std::to_string(lightings.size()) + " image(s) of lightings" +
        (out.left_out.empty() ? ""
                              : " (" + std::to_string(out.left_out.size()) +
                                    " left out by the include/exclude patterns)") +
        "; a single lighting gives no invariant image, at least 2 are needed");
  for (const fs::path& p : lightings) {
    out.images.push_back(ReadImage(p));
    out.names.push_back(p.filename().string());
    const cv::Mat& first = out.images.front();
    const cv::Mat& last = out.images.back();
    if (last.size() != first.size() || last.channels() != first.channels())
      throw std::runtime_error(p.string() + " is " + Describe(last) + ", " + out.names.front() +
                               " " + Describe(first) +
                               ": all lightings must be images of one viewpoint and size");
  }
  const cv::Size size = out.images.front().size();
  auto check = [&](const cv::Mat& m, const char* name) {
    if (!m.empty() && m.size() != size)
      throw std::runtime_error(folder + "/" + name + " is " + Describe(m) + ", the lightings are " +
                               Describe(out.images.front()));
  };
  check(out.mask, "mask");
  check(out.reflectance, "reflectance");
  check(out.shading, "shading");
  check(out.diffuse, "diffuse");
  return out;
}

}  // namespace novelty::sensors
