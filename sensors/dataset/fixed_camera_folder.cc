#include "sensors/dataset/fixed_camera_folder.h"

#include <cctype>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "core/frame_stem.h"
#include "sensors/dataset/cdnet_folder.h"
#include "sensors/dataset/rgbd_importer.h"
#include "sensors/rawlog/camera_pose_observation.h"
#include "sensors/rawlog/rawlog_output.h"
#include "sensors/rawlog/rgbd_observation.h"

namespace novelty::sensors {
namespace {

// The image's size: from the header where ReadImageHeader knows the format (before anything is
// decoded), else by decoding it into `decoded` (TIFF, PNM), the limit checked after the fact.
cv::Size SizeOf(const std::string& path, long long max_pixels, cv::Mat* decoded) {
  std::string ext = path.substr(path.find_last_of('.') + 1);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "png" || ext == "jpg" || ext == "jpeg" || ext == "bmp")
    return CheckImageHeader(path, max_pixels).size;
  *decoded = ReadFolderImage(path);
  if (decoded->total() > std::size_t(max_pixels))
    throw std::runtime_error(path + ": " + std::to_string(decoded->total()) +
                             " pixels, over the limit of " + std::to_string(max_pixels));
  return decoded->size();
}

}  // namespace

FixedCameraFolder::FixedCameraFolder(const std::string& folder, const FixedCameraOptions& o)
    : folder_(folder), options_(o), listing_(ListImageFolder(folder, o.pick)) {
  if (!(o.depth > 0.0 && o.depth < kRgbdMaxDepth))
    throw std::invalid_argument("fixed camera: depth must be in (0, " +
                                std::to_string(kRgbdMaxDepth) + ") m");
  if (listing_.images.empty())
    throw std::runtime_error(folder + ": no image" +
                             (listing_.left_out.empty()
                                  ? ""
                                  : " (" + std::to_string(listing_.left_out.size()) +
                                        " left out by the include/exclude patterns)"));
  if (!o.mask.empty()) listing_.mask = o.mask;
  cv::Mat unused;
  const cv::Size size = SizeOf(listing_.images.front(), o.max_pixels, &unused);
  camera_ = NominalCamera(size);
  depth_ = cv::Mat(size, CV_32F, cv::Scalar(o.depth));
  if (!listing_.mask.empty()) {
    const cv::Mat mask = ReadFolderMask(listing_.mask);
    if (mask.size() != size)
      throw std::runtime_error(listing_.mask + " is " + std::to_string(mask.cols) + "x" +
                               std::to_string(mask.rows) + ", the images " +
                               std::to_string(size.width) + "x" + std::to_string(size.height));
    depth_.setTo(0.0f, mask == 0);
  }
}

FixedCameraFolder CdnetFixedCamera(const std::string& dir, FixedCameraOptions options) {
  const CdnetFolder cdnet = ReadCdnetFolder(dir);  // input/ and its frame names checked
  if (!cdnet.roi.empty()) options.mask = dir + "/ROI.bmp";
  options.pick.include = {"in*"};
  return FixedCameraFolder(dir + "/input", options);
}

std::string FixedCameraFolder::name(int k) const {
  const std::string& p = listing_.images.at(std::size_t(k));
  return p.substr(p.find_last_of('/') + 1);
}

core::PinholeCamera NominalCamera(const cv::Size& size) {
  core::PinholeCamera c;
  c.width = size.width, c.height = size.height;
  c.fx = c.fy = std::max(size.width, size.height);
  c.cx = 0.5 * (size.width - 1), c.cy = 0.5 * (size.height - 1);
  return c;
}

cv::Mat ReadImageRgb8(const std::string& path, long long max_pixels,
                      const std::function<void(const cv::Size&)>& check_size) {
  cv::Mat image;
  const cv::Size size = SizeOf(path, max_pixels, &image);
  if (check_size) check_size(size);
  if (image.empty()) image = ReadFolderImage(path);
  if (image.size() != size)
    throw std::runtime_error(path + ": decodes to another size than its header says");
  if (image.depth() == CV_16U) image.convertTo(image, CV_8U, 1.0 / 257.0);
  if (image.channels() == 1) cv::cvtColor(image, image, cv::COLOR_GRAY2RGB);
  return image;
}

cv::Mat FixedCameraFolder::Rgb(int k) const {
  const std::string& path = listing_.images.at(std::size_t(k));
  return ReadImageRgb8(path, options_.max_pixels, [&](const cv::Size& size) {
    if (size.width != camera_.width || size.height != camera_.height)
      throw std::runtime_error(
          path + " is " + std::to_string(size.width) + "x" + std::to_string(size.height) + ", " +
          name(0) + " " + std::to_string(camera_.width) + "x" + std::to_string(camera_.height) +
          ": a fixed camera's images share one size");
  });
}

mrpt::obs::CObservation3DRangeScan FixedCameraFolder::Observation(int k) const {
  return MakeRgbdObservation(double(k), Rgb(k), depth_, camera_, HandHeldMount());
}

RgbdImportResult ImportFixedCameraFolder(const FixedCameraFolder& folder, const std::string& path,
                                         const RgbdImportOptions& o) {
  const int last = LastImportedFrame(o, folder.size());
  const int total = (last - o.first) / o.every + 1;
  RawlogOutput out(path);
  RgbdImportResult r;
  const Eigen::Isometry3d mount = HandHeldMount();
  const double known =
      double(cv::countNonZero(folder.depth() > 0)) / double(folder.depth().total());
  for (int k = o.first; k <= last; k += o.every) {
    const double time = double(k);
    // The camera where Observation(k) puts it when inserted with the robot at the origin, so that
    // a map learnt from the folder judges the rawlog and the other way round.
    out.Write(MakeCameraPoseObservation(time, mount, mount, "POSE_DATASET", 0.0, 0.0));
    out.WriteRgbd(time, folder.Rgb(k - 1), folder.depth(), folder.camera(), mount,
                  core::FrameStem(k));
    ++r.frames, ++r.posed;
    if (o.progress) o.progress(r.frames, total);
  }
  out.Close();
  r.depth_coverage = known;
  return r;
}

}  // namespace novelty::sensors
