#include "experiments/object_finder_run.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>

#include "core/csv_field.h"
#include "core/frame.h"
#include "core/write_rgb_image.h"
#include "maps/objects/feature_extractor.h"
#include "mrpt_plugins/c_object_database_map.h"
#include "sensors/dataset/fixed_camera_folder.h"
#include "sensors/rawlog/brief_message.h"
#include "sensors/rawlog/rawlog_frame_reader.h"

namespace novelty::experiments {

namespace fs = std::filesystem;

namespace {

// Frames one at a time from an image, a folder of images or a rawlog.
class FrameSource {
 public:
  FrameSource(const ObjectFinderRunOptions& o) : o_(o) {
    if (fs::path(o.input).extension() == ".rawlog") {
      rawlog_ = std::make_unique<sensors::RawlogFrameReader>(o.input);
    } else if (fs::is_directory(o.input)) {
      images_ = sensors::ListImageFolder(o.input, o.pick).images;
      if (images_.empty()) throw std::runtime_error(o.input + ": no image");
    } else {
      images_ = {o.input};
    }
  }
  int total() const { return rawlog_ ? 0 : int(images_.size()); }
  const std::vector<std::string>& skip_reasons() const {
    return rawlog_ ? rawlog_->skip_reasons() : skips_;
  }
  /// Why a rawlog ended before its end (truncated, corrupt); empty if it did not.
  const std::string& stopped_by() const { return stopped_by_; }

  // The next frame; false at the end. An image that cannot be read, or a rawlog frame that
  // cannot be decoded, is skipped and counted; a rawlog that cannot be read on stops the run.
  bool Next(core::Frame& f) {
    if (rawlog_) {
      try {
        return rawlog_->Next(f);
      } catch (const std::exception& e) {
        stopped_by_ = sensors::BriefMessage(e);
        return false;
      }
    }
    while (next_ < images_.size()) {
      const std::string& path = images_[next_++];
      f = core::Frame();
      f.index = int(next_);
      f.label = fs::path(path).filename().string();
      try {
        f.rgb = sensors::ReadImageRgb8(path, o_.max_pixels, [&](const cv::Size& size) {
          if (o_.camera && (size.width != o_.camera->width || size.height != o_.camera->height))
            throw std::runtime_error(path + " is " + std::to_string(size.width) + "x" +
                                     std::to_string(size.height) + ", the given camera's " +
                                     std::to_string(o_.camera->width) + "x" +
                                     std::to_string(o_.camera->height));
        });
      } catch (const std::runtime_error& e) {
        skips_.push_back(sensors::BriefMessage(e));
        continue;
      }
      f.camera = o_.camera ? *o_.camera : sensors::NominalCamera(f.rgb.size());
      return true;
    }
    return false;
  }

 private:
  const ObjectFinderRunOptions& o_;
  std::unique_ptr<sensors::RawlogFrameReader> rawlog_;
  std::vector<std::string> images_, skips_;
  std::size_t next_ = 0;
  std::string stopped_by_;
};

std::string Xyz(const Eigen::Vector3d& p) {
  if (!p.allFinite()) return ",,";
  std::ostringstream s;
  s.precision(4);
  s << std::fixed << p.x() << ',' << p.y() << ',' << p.z();
  return s.str();
}

std::string CsvRow(const core::Frame& f, const objects::FoundObject& o,
                   const Eigen::Vector3d& world) {
  std::ostringstream outline;
  outline.precision(1);
  outline << std::fixed;
  for (std::size_t i = 0; i < o.outline.size(); ++i)
    outline << (i ? ";" : "") << o.outline[i].x << ' ' << o.outline[i].y;
  const cv::Rect b = cv::boundingRect(o.outline);
  std::ostringstream row;
  row << f.index << ',' << core::CsvField(f.label) << ',' << core::CsvField(o.name) << ','
      << (o.verified ? "yes" : "no") << ',' << o.matches << ',' << o.inliers << ','
      << core::CsvField(outline.str()) << ',' << b.x << ',' << b.y << ',' << b.width << ','
      << b.height << ',' << Xyz(o.place) << ',' << Xyz(world) << '\n';
  return row.str();
}

void DrawFound(cv::Mat& rgb, const std::vector<objects::FoundObject>& found) {
  const int thick = std::max(1, rgb.cols / 320);
  for (const objects::FoundObject& o : found) {
    const cv::Scalar colour = o.verified ? cv::Scalar(40, 220, 40) : cv::Scalar(255, 150, 0);
    std::vector<cv::Point> poly;
    for (const cv::Point2f& p : o.outline)
      poly.emplace_back(int(std::lround(p.x)), int(std::lround(p.y)));
    cv::polylines(rgb, poly, true, colour, thick, cv::LINE_AA);
    const cv::Rect b = cv::boundingRect(poly);
    cv::putText(rgb, o.name + (o.verified ? "" : "?"),
                cv::Point(std::max(0, b.x), std::max(12 * thick, b.y - 3 * thick)),
                cv::FONT_HERSHEY_SIMPLEX, 0.45 * thick, colour, thick, cv::LINE_AA);
  }
}

void Report(std::FILE* console, const core::Frame& f, const objects::FoundObject& o,
            const Eigen::Vector3d& world) {
  if (!console) return;
  const cv::Rect b = cv::boundingRect(o.outline);
  std::fprintf(console, "  frame %d (%s): %s %s, %d matches%s, box %d,%d %dx%d px", f.index,
               f.label.c_str(), o.name.c_str(), o.verified ? "verified" : "not verified", o.matches,
               o.verified ? (", " + std::to_string(o.inliers) + " agree").c_str() : "", b.x, b.y,
               b.width, b.height);
  if (world.allFinite())
    std::fprintf(console, ", at %.2f %.2f %.2f m (world)", world.x(), world.y(), world.z());
  else if (o.place.allFinite())
    std::fprintf(console, ", at %.2f %.2f %.2f m (camera)", o.place.x(), o.place.y(), o.place.z());
  std::fprintf(console, "\n");
}

}  // namespace

ObjectFinderRunResult RunObjectFinder(const ObjectFinderRunOptions& o, const std::string& out) {
  mrpt_plugins::CObjectDatabaseMap map;
  map.LoadFromFile(o.database);
  const objects::FeatureDatabase& db = map.database();
  if (db.objects() == 0 || db.features() == 0)
    throw std::runtime_error(o.database + ": the database holds no object");
  const cv::Ptr<cv::Feature2D> extractor =
      objects::CreateFeatureExtractor(map.config().map.extractor);
  FrameSource source(o);
  fs::create_directories(fs::path(out) / "panels");
  std::ofstream csv(fs::path(out) / "found.csv");
  csv << "frame,source,object,verified,matches,inliers,outline_px,box_x,box_y,box_w,box_h,"
         "camera_x,camera_y,camera_z,world_x,world_y,world_z\n";
  ObjectFinderRunResult r;
  int panels = 0;
  for (core::Frame f; source.Next(f);) {
    ++r.frames;
    cv::Mat grey;
    cv::cvtColor(f.rgb, grey, cv::COLOR_RGB2GRAY);
    const cv::Mat depth = f.depth.size() == f.rgb.size() ? f.depth : cv::Mat();
    const std::vector<objects::FoundObject> found = objects::FindObjects(
        objects::ExtractFrameFeatures(grey, *extractor), depth, db, f.camera, o.finder);
    for (const objects::FoundObject& x : found) {
      const Eigen::Vector3d world = f.T_world_cam && x.place.allFinite()
                                        ? Eigen::Vector3d(*f.T_world_cam * x.place)
                                        : Eigen::Vector3d::Constant(std::nan(""));
      csv << CsvRow(f, x, world);
      Report(o.console, f, x, world);
      ObjectSightings& s = r.objects[x.name];
      if (s.frames++ == 0) s.first = f.index;
      s.last = f.index;
      s.verified += x.verified;
    }
    if (!found.empty() && panels < o.max_panels) {
      ++panels;
      DrawFound(f.rgb, found);
      core::WriteRgbImage((fs::path(out) / "panels" / (std::to_string(f.index) + ".png")).string(),
                          f.rgb);
    }
    if (o.progress) o.progress(r.frames, source.total());
  }
  r.skip_reasons = source.skip_reasons();
  r.skipped = int(r.skip_reasons.size());
  r.stopped_by = source.stopped_by();
  if (r.frames == 0)
    throw std::runtime_error(o.input + ": no frame could be used" +
                             (!r.stopped_by.empty()     ? " (" + r.stopped_by + ")"
                              : !r.skip_reasons.empty() ? " (" + r.skip_reasons.front() + ")"
                                                        : " (no camera frame in it)"));
  std::ofstream summary(fs::path(out) / "objects.csv");
  summary << "object,frames_found,frames_verified,first_frame,last_frame\n";
  for (const auto& [name, s] : r.objects)
    summary << core::CsvField(name) << ',' << s.frames << ',' << s.verified << ',' << s.first << ','
            << s.last << '\n';
  if (!csv || !summary) throw std::runtime_error(out + ": cannot write found.csv or objects.csv");
  return r;
}

}  // namespace novelty::experiments
