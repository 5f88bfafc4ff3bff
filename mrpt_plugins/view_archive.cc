#include "mrpt_plugins/view_archive.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/depth_check.h"
#include "maps/views/plane_codec.h"
#include "mrpt_plugins/map_formats.h"
#include "mrpt_plugins/option_table.h"

namespace novelty::mrpt_plugins {

namespace {

// Type, size, then the bytes of an encoded plane.
void WriteEncoded(mrpt::serialization::CArchive& out, const views::EncodedView::Plane& p,
                  const core::PinholeCamera& camera) {
  out << int32_t(p.type) << int32_t(camera.height) << int32_t(camera.width);
  out << uint32_t(p.bytes.size());
  out.WriteBuffer(p.bytes.data(), p.bytes.size());
}

// Type, size, then the raw values (MapFormat::raw_planes).
void WriteRaw(mrpt::serialization::CArchive& out, const cv::Mat& m) {
  out << int32_t(m.type()) << int32_t(m.rows) << int32_t(m.cols);
  const cv::Mat c = m.isContinuous() ? m : m.clone();
  out.WriteBuffer(c.data, c.total() * c.elemSize());
}

// `bytes` bytes, allocated in chunks as they arrive: a corrupt or cut file fails after at most a
// chunk more than it holds, instead of first asking for the gigabytes its header claims.
std::vector<uint8_t> ReadChunked(mrpt::serialization::CArchive& in, std::size_t bytes) {
  constexpr std::size_t kChunk = std::size_t(1) << 22;
  std::vector<uint8_t> data;
  while (data.size() < bytes) {
    const std::size_t at = data.size(), n = std::min(kChunk, bytes - at);
    data.resize(at + n);
    in.ReadBuffer(data.data() + at, n);
  }
  return data;
}

// The type and byte count of an image of the view's size and of a type maps store, checked
// before anything is allocated.
int ReadImageHeader(mrpt::serialization::CArchive& in, const core::PinholeCamera& camera,
                    const std::string& what, std::size_t& bytes) {
  int32_t type, rows, cols;
  in >> type >> rows >> cols;
  if (rows != camera.height || cols != camera.width) {
    ThrowMapFileError(what + " is " + std::to_string(cols) + "x" + std::to_string(rows) +
                      ", the view's camera " + std::to_string(camera.width) + "x" +
                      std::to_string(camera.height));
  }
  const int depth = CV_MAT_DEPTH(type), channels = CV_MAT_CN(type);
  const bool known_depth = depth == CV_8U || depth == CV_16U || depth == CV_16F || depth == CV_32F;
  if (type < 0 || !known_depth || channels > 64) {  // 64: an illumination map's lightings
    ThrowMapFileError(what + " has an unknown type " + std::to_string(type));
  }
  bytes = std::size_t(rows) * cols * CV_ELEM_SIZE(type);
  if (bytes > (std::size_t(1) << 28)) ThrowMapFileError(what + " is over 256 MB");
  return type;
}

// An encoded image as WriteEncoded writes it, not yet decoded.
views::EncodedView::Plane ReadEncoded(mrpt::serialization::CArchive& in,
                                      const core::PinholeCamera& camera, const std::string& what) {
  std::size_t bytes = 0;
  views::EncodedView::Plane p;
  p.type = ReadImageHeader(in, camera, what, bytes);
  uint32_t size = 0;
  in >> size;
  if (size > bytes + bytes / 8 + 1024)  // more than zstd's worst case for the plane
    ThrowMapFileError(what + ": implausible encoded size");
  p.bytes = ReadChunked(in, size);
  return p;
}

// A raw image as WriteRaw writes it.
cv::Mat ReadRaw(mrpt::serialization::CArchive& in, const core::PinholeCamera& camera,
                const std::string& what) {
  std::size_t bytes = 0;
  const int type = ReadImageHeader(in, camera, what, bytes);
  const std::vector<uint8_t> data = ReadChunked(in, bytes);
  cv::Mat m(camera.height, camera.width, type);
  if (bytes > 0) std::memcpy(m.data, data.data(), bytes);
  return m;
}

// The view's camera: a size maps can hold, finite focal lengths and principal point.
core::PinholeCamera ReadCamera(mrpt::serialization::CArchive& in, const std::string& what) {
  int32_t w, h;
  core::PinholeCamera c;
  in >> w >> h >> c.fx >> c.fy >> c.cx >> c.cy;
  if (w < 1 || h < 1 || w > 8192 || h > 8192)
    ThrowMapFileError(what + ": implausible camera size " + std::to_string(w) + "x" +
                      std::to_string(h));
  c.width = w;
  c.height = h;
  try {
    c.Check();
  } catch (const std::invalid_argument& e) {
    ThrowMapFileError(what + ": " + e.what());
  }
  return c;
}

// Depth as maps take it (core/depth_check.h).
void CheckDepth(const cv::Mat& depth, const std::string& what) {
  if (const int n = core::CountBrokenDepths(depth); n > 0)
    ThrowMapFileError(what + ": " + std::to_string(n) + " negative or infinite depths");
}

void WritePose(mrpt::serialization::CArchive& out, const Eigen::Isometry3d& p) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) out << p.matrix()(r, c);
}

Eigen::Isometry3d ReadPose(mrpt::serialization::CArchive& in) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) in >> p.matrix()(r, c);
  return p;
}

// A view's depth and named planes after its camera and pose, raw or encoded as `format` says
// (decoded into `v` here). `e` keeps the encoding a compact store may hold.
void ReadPlanes(mrpt::serialization::CArchive& in, const std::string& what, const MapFormat& format,
                views::EncodedView& e, views::ReferenceView& v) {
  e.encoding = format.encoding;
  const auto read = [&](const std::string& name, const std::string& plane) {
    if (format.raw_planes)
      (name.empty() ? v.depth : v.planes[name]) = ReadRaw(in, v.camera, plane);
    else
      e.planes[name] = ReadEncoded(in, v.camera, plane);
  };
  read("", what + " depth");
  int32_t planes;
  in >> planes;
  if (planes < 0 || planes > 16) ThrowMapFileError(what + ": implausible plane count");
  for (int32_t k = 0; k < planes; ++k) {
    const std::string name = ReadShortString(in, 64, what + " plane name");
    if (name.empty()) ThrowMapFileError(what + ": a plane without a name");
    read(name, what + " plane '" + name + "'");
  }
  if (!format.raw_planes) {
    try {
      views::DecodeInto(e, v);
    } catch (const std::runtime_error& error) {
      ThrowMapFileError(what + " " + error.what());
    }
  }
  CheckDepth(v.depth, what);
}

// The encoded depth and planes of a view, as ReadPlanes reads them.
void WritePlanes(mrpt::serialization::CArchive& out, const views::EncodedView& e,
                 const core::PinholeCamera& c) {
  WriteEncoded(out, e.planes.at(""), c);
  out << int32_t(e.planes.size() - 1);
  for (const auto& [name, plane] : e.planes) {
    if (name.empty()) continue;
    out << name;
    WriteEncoded(out, plane, c);
  }
}

}  // namespace

void WriteViewMap(mrpt::serialization::CArchive& out, const appearance::ViewBasedMap& map,
                  const MapFormat& format) {
  const views::ReferenceViewStore& store = map.store();
  const bool as_held = format.encoding == views::PlaneEncoding::kPredicted;
  views::PlaneCodecOptions codec;
  codec.encoding = format.encoding;
  out << int32_t(store.size());
  for (int j = 0; j < store.size(); ++j) {
    const core::PinholeCamera& c = store.camera(j);
    out << int32_t(c.width) << int32_t(c.height) << c.fx << c.fy << c.cx << c.cy;
    WritePose(out, store.pose(j));
    WritePose(out, map.anchors()[std::size_t(j)]);
    if (format.raw_planes) {
      const views::ReferenceView v = store.Decoded(j);
      WriteRaw(out, v.depth);
      out << int32_t(v.planes.size());
      for (const auto& [name, plane] : v.planes) {
        out << name;
        WriteRaw(out, plane);
      }
    } else {
      // What a compact map holds already, else encoded now, a view at a time.
      WritePlanes(out, as_held ? store.Encoded(j) : views::EncodeView(store.Decoded(j), codec), c);
    }
  }
}

void ReadViewMap(mrpt::serialization::CArchive& in, appearance::ViewBasedMap& map,
                 const MapFormat& format) {
  int32_t n;
  in >> n;
  if (n < 0 || n > 1000000) ThrowMapFileError("corrupt view count");
  std::vector<views::ReferenceView> views;
  std::vector<views::EncodedView> encoded;  // kept as they are by a compact map
  const bool as_held = !format.raw_planes && format.encoding == views::PlaneEncoding::kPredicted;
  const bool compact = map.store().options().decoded_views > 0;
  std::vector<Eigen::Isometry3d> anchors;
  for (int32_t j = 0; j < n; ++j) {
    const std::string what = "view " + std::to_string(j);
    views::ReferenceView v;
    v.camera = ReadCamera(in, what);
    v.T_world_cam = ReadPose(in);
    anchors.push_back(ReadPose(in));
    views::EncodedView e;
    ReadPlanes(in, what, format, e, v);
    if (as_held && compact) {  // held as it was read: no second copy of 200 views decoded
      v.depth.release();
      v.planes.clear();
    }
    views.push_back(std::move(v));
    if (as_held) encoded.push_back(std::move(e));
  }
  map.Restore(std::move(views), std::move(anchors), std::move(encoded));
}

void WriteView(mrpt::serialization::CArchive& out, const views::ReferenceView& view) {
  const core::PinholeCamera& c = view.camera;
  out << int32_t(c.width) << int32_t(c.height) << c.fx << c.fy << c.cx << c.cy;
  WritePose(out, view.T_world_cam);
  WritePlanes(out, views::EncodeView(view, {}), c);
}

views::ReferenceView ReadView(mrpt::serialization::CArchive& in, const std::string& what) {
  views::ReferenceView v;
  v.camera = ReadCamera(in, what);
  v.T_world_cam = ReadPose(in);
  views::EncodedView e;
  ReadPlanes(in, what, MapFormat{}, e, v);
  try {
    v.Check(what);
  } catch (const std::invalid_argument& error) {
    ThrowMapFileError(error.what());
  }
  return v;
}

}  // namespace novelty::mrpt_plugins
