#include "maps/views/reference_view_store.h"
#include "core/rigid_pose.h"

#include <algorithm>
#include <opencv2/core/utility.hpp>
#include <stdexcept>

namespace novelty::views {

namespace {

// The depth (key "") and planes of a view, to encode or decode each on its own thread.
std::vector<std::pair<std::string, cv::Mat*>> Images(ReferenceView& v) {
  std::vector<std::pair<std::string, cv::Mat*>> images = {{"", &v.depth}};
  for (auto& [name, plane] : v.planes) images.emplace_back(name, &plane);
  return images;
}

}  // namespace

void ReferenceView::Check(const std::string& what) const {
  camera.Check();
  if (!core::IsRigid(T_world_cam)) {
    throw std::invalid_argument(what + ": pose is not a rigid transform");
  }
  if (depth.type() != CV_32FC1 || depth.rows != camera.height || depth.cols != camera.width) {
    throw std::invalid_argument(
        what + ": depth must be CV_32FC1 of " + std::to_string(camera.width) + "x" +
        std::to_string(camera.height) + ", got " + std::to_string(depth.cols) + "x" +
        std::to_string(depth.rows) + " of type " + std::to_string(depth.type()));
  }
  for (const auto& [name, plane] : planes) {
    if (plane.rows != depth.rows || plane.cols != depth.cols) {
      throw std::invalid_argument(what + ": plane '" + name + "' is " + std::to_string(plane.cols) +
                                  "x" + std::to_string(plane.rows) + ", depth is " +
                                  std::to_string(depth.cols) + "x" + std::to_string(depth.rows));
    }
  }
}

ReferenceView ReferenceViewOf(const core::Frame& frame, const std::string& plane) {
  if (!frame.T_world_cam) {
    throw std::invalid_argument("frame " + std::to_string(frame.index) +
                                ": no pose, cannot become a reference view");
  }
  ReferenceView v;
  v.camera = frame.camera;
  v.T_world_cam = *frame.T_world_cam;
  v.depth = frame.depth;
  v.planes[plane] = frame.rgb;
  return v;
}

std::size_t ReferenceView::BytesUsed() const {
  std::size_t bytes = depth.total() * depth.elemSize();
  for (const auto& [name, plane] : planes) bytes += plane.total() * plane.elemSize();
  return bytes;
}

std::size_t EncodedView::BytesUsed() const {
  std::size_t bytes = 0;
  for (const auto& [name, plane] : planes) bytes += plane.bytes.size();
  return bytes;
}

EncodedView EncodeView(const ReferenceView& view, const PlaneCodecOptions& codec) {
  ReferenceView v = view;  // shallow: the images are shared, not copied
  const auto images = Images(v);
  std::vector<EncodedView::Plane> encoded(images.size());
  cv::parallel_for_(cv::Range(0, int(images.size())), [&](const cv::Range& r) {
    for (int k = r.start; k < r.end; ++k) {
      const cv::Mat& m = *images[std::size_t(k)].second;
      encoded[std::size_t(k)] = {m.type(), EncodePlane(m, codec)};
    }
  });
  EncodedView out;
  out.encoding = codec.encoding;
  for (std::size_t k = 0; k < images.size(); ++k)
    out.planes[images[k].first] = std::move(encoded[k]);
  return out;
}

void DecodeInto(const EncodedView& encoded, ReferenceView& view) {
  std::vector<std::pair<const std::string*, const EncodedView::Plane*>> planes;
  for (const auto& [name, plane] : encoded.planes) planes.emplace_back(&name, &plane);
  std::vector<cv::Mat> images(planes.size());
  std::vector<std::string> errors(planes.size());
  const int rows = view.camera.height, cols = view.camera.width;
  cv::parallel_for_(cv::Range(0, int(planes.size())), [&](const cv::Range& r) {
    for (int k = r.start; k < r.end; ++k) {
      const EncodedView::Plane& p = *planes[std::size_t(k)].second;
      try {
        images[std::size_t(k)] =
            DecodePlane(p.bytes.data(), p.bytes.size(), rows, cols, p.type, encoded.encoding);
      } catch (const std::exception& e) {
        errors[std::size_t(k)] = e.what();
      }
    }
  });
  for (std::size_t k = 0; k < planes.size(); ++k) {
    const std::string what =
        planes[k].first->empty() ? "depth" : "plane '" + *planes[k].first + "'";
    if (!errors[k].empty()) throw std::runtime_error(what + ": " + errors[k]);
  }
  view.planes.clear();
  for (std::size_t k = 0; k < planes.size(); ++k) {
    if (planes[k].first->empty())
      view.depth = images[k];
    else
      view.planes[*planes[k].first] = images[k];
  }
}

ReferenceViewStore::ReferenceViewStore(const ReferenceViewStoreOptions& options)
    : options_(options) {
  if (options.decoded_views < 0)
    throw std::invalid_argument("ReferenceViewStore: decoded_views must be ≥ 0");
}

int ReferenceViewStore::Add(ReferenceView view, EncodedView encoded) {
  const std::string what = "reference view " + std::to_string(views_.size());
  if (view.depth.empty() && !encoded.planes.empty()) {  // a view given encoded only
    if (options_.decoded_views > 0) {
      view.camera.Check();
      if (!core::IsRigid(view.T_world_cam))
        throw std::invalid_argument(what + ": pose is not a rigid transform");
      views_.push_back(std::move(view));
      encoded_.push_back(std::move(encoded));
      last_use_.push_back(0);
      return size() - 1;
    }
    try {
      DecodeInto(encoded, view);
    } catch (const std::runtime_error& e) {
      throw std::invalid_argument(what + ": " + e.what());
    }
  }
  view.Check(what);
  views_.push_back(std::move(view));
  encoded_.push_back(options_.decoded_views > 0 ? std::move(encoded) : EncodedView{});
  last_use_.push_back(++clock_);
  return size() - 1;
}

void ReferenceViewStore::Replace(int i, ReferenceView view) {
  if (i < 0 || i >= size()) {
    throw std::out_of_range("ReferenceViewStore::Replace: no view " + std::to_string(i));
  }
  view.Check("reference view " + std::to_string(i));
  views_[std::size_t(i)] = std::move(view);
  encoded_[std::size_t(i)] = {};  // changed: encoded again when evicted
  last_use_[std::size_t(i)] = ++clock_;
}

ReferenceView& ReferenceViewStore::Entry(int i) const {
  if (i < 0 || i >= size()) {
    throw std::out_of_range("ReferenceViewStore: no view " + std::to_string(i));
  }
  return views_[std::size_t(i)];
}

const ReferenceView& ReferenceViewStore::view(int i) const {
  ReferenceView& v = Entry(i);
  if (v.depth.empty()) {
    DecodeInto(encoded_[std::size_t(i)], v);
    ++counts_.decoded;
  }
  last_use_[std::size_t(i)] = ++clock_;
  return v;
}

ReferenceView ReferenceViewStore::Decoded(int i) const {
  ReferenceView v = Entry(i);
  if (v.depth.empty()) DecodeInto(encoded_[std::size_t(i)], v);
  return v;
}

EncodedView ReferenceViewStore::Encoded(int i) const {
  const ReferenceView& v = Entry(i);
  EncodedView& e = encoded_[std::size_t(i)];
  if (!e.planes.empty()) return e;
  EncodedView now = EncodeView(v, options_.codec);
  ++counts_.encoded;
  if (options_.decoded_views > 0) e = now;
  return now;
}

std::vector<int> ReferenceViewStore::Trim(const std::vector<int>& keep) {
  std::vector<int> evicted;
  if (options_.decoded_views == 0) return evicted;
  std::vector<std::pair<uint64_t, int>> candidates;  // (last use, view)
  int decoded_count = 0;
  for (int j = 0; j < size(); ++j) {
    if (!decoded(j)) continue;
    ++decoded_count;
    if (std::find(keep.begin(), keep.end(), j) == keep.end())
      candidates.emplace_back(last_use_[std::size_t(j)], j);
  }
  std::sort(candidates.begin(), candidates.end());
  for (const auto& [use, j] : candidates) {
    if (decoded_count <= options_.decoded_views) break;
    EncodedView& e = encoded_[std::size_t(j)];
    if (e.planes.empty()) {
      e = EncodeView(views_[std::size_t(j)], options_.codec);
      ++counts_.encoded;
    }
    ReferenceView& v = views_[std::size_t(j)];
    v.depth.release();
    v.planes.clear();
    --decoded_count;
    evicted.push_back(j);
  }
  return evicted;
}

std::vector<Eigen::Isometry3d> ReferenceViewStore::Poses() const {
  std::vector<Eigen::Isometry3d> poses;
  poses.reserve(views_.size());
  for (const ReferenceView& v : views_) poses.push_back(v.T_world_cam);
  return poses;
}

std::size_t ReferenceViewStore::BytesUsed() const {
  std::size_t bytes = 0;
  for (std::size_t j = 0; j < views_.size(); ++j)
    bytes += views_[j].BytesUsed() + encoded_[j].BytesUsed();
  return bytes;
}

}  // namespace novelty::views
