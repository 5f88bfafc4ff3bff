// Reference views of an image-based map (thesis ch. 3): per view the intrinsics, the pose
// T_world_cam, a depth map and any number of named per-pixel planes (an image, normal-gamma
// parameter planes, an illumination-invariant image, …). Geometry (camera, pose, depth) and data
// (planes) stay apart, so one warp serves every plane.
//
// Memory: depth is kept as CV_32F; planes keep the type they are given (CV_8U, CV_16F, CV_32F,
// any channel count), so a map stores what it needs at the precision it needs. With
// `decoded_views` > 0 the store holds the views compact (plane_codec.h: rounded and predicted,
// about a quarter of their size) and at most that many decoded — the ones used last, a cache
// that Trim() keeps to size. A view enters the cache decoded when it is added or replaced, or
// when view() asks for it; it is encoded when Trim() evicts it (a view used for a prediction is
// replaced by the next frame's posterior before it has to be). Its planes are then the rounded
// values a saved map holds. BytesUsed() reports the total, compact and decoded.
// view() decodes into the cache although it is const: one thread at a time uses a store.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <map>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/eigen_abi.h"
#include "core/frame.h"
#include "core/pinhole_camera.h"
#include "maps/views/plane_codec.h"

namespace novelty::views {

struct ReferenceView {
  core::PinholeCamera camera;
  Eigen::Isometry3d T_world_cam = Eigen::Isometry3d::Identity();
  cv::Mat depth;                          ///< CV_32F metres along +Z; 0 or NaN = unknown
  std::map<std::string, cv::Mat> planes;  ///< same size as depth, any type

  /// Throws std::invalid_argument naming `what` and the problem: a pose that is not a rigid
  /// transform, a depth map of the wrong size or type, a plane of the wrong size.
  void Check(const std::string& what) const;
  std::size_t BytesUsed() const;
};

/// A view's depth and planes as EncodePlane gives them (the key "" is the depth).
struct EncodedView {
  struct Plane {
    int type = 0;
    std::vector<uint8_t> bytes;
  };
  std::map<std::string, Plane> planes;
  PlaneEncoding encoding = PlaneEncoding::kPredicted;
  std::size_t BytesUsed() const;
};

/// A frame with a pose as a reference view holding its image as plane `plane`. Throws
/// std::invalid_argument naming the frame if it has no pose.
ReferenceView ReferenceViewOf(const core::Frame& frame, const std::string& plane = "rgb");

struct ReferenceViewStoreOptions {
  /// Views held decoded at most (the cache Trim() keeps); 0: every view decoded, none encoded.
  /// Each decoded 320×240 appearance-map view takes 2.3 MB, each compact one about 0.57 MB.
  int decoded_views = 0;
  PlaneCodecOptions codec;  ///< how compact views are encoded (plane_codec.h defaults)
};

class ReferenceViewStore {
 public:
  explicit ReferenceViewStore(const ReferenceViewStoreOptions& options = {});

  /// Adds a view (checked) and returns its index. `encoded`: the same view as EncodeView gives
  /// it (a loaded map's), kept instead of encoding the view again when it is evicted; the view
  /// may then come without depth and planes (held compact, or decoded now if the store is not
  /// compact).
  int Add(ReferenceView view, EncodedView encoded = {});
  /// Replaces view i (checked); the update policy of 4.3 replaces views in place.
  void Replace(int i, ReferenceView view);

  /// View i, decoded (into the cache if the store is compact: it stays there at least until
  /// the next Trim()). References stay valid until then.
  const ReferenceView& view(int i) const;
  /// View i decoded without entering the cache (a shallow copy if it is decoded): for passes
  /// over every view — saving, checking, drawing — that would otherwise decode them all at once.
  ReferenceView Decoded(int i) const;
  /// View i's depth and planes encoded: the store's encoding if it holds one, else encoded now
  /// (and kept, if the store is compact).
  EncodedView Encoded(int i) const;
  /// Evicts the least recently used decoded views, encoding them, until at most
  /// `decoded_views` are decoded, never one of `keep`. Returns the views evicted. Nothing when
  /// the store is not compact.
  std::vector<int> Trim(const std::vector<int>& keep = {});

  int size() const { return static_cast<int>(views_.size()); }
  bool decoded(int i) const { return !views_.at(std::size_t(i)).depth.empty(); }
  const core::PinholeCamera& camera(int i) const { return views_.at(std::size_t(i)).camera; }
  const Eigen::Isometry3d& pose(int i) const { return views_.at(std::size_t(i)).T_world_cam; }
  std::vector<Eigen::Isometry3d> Poses() const;
  std::size_t BytesUsed() const;
  const ReferenceViewStoreOptions& options() const { return options_; }
  /// Views encoded and decoded so far (a compact store's work, for reports and benchmarks).
  struct Counts {
    long encoded = 0, decoded = 0;
  };
  Counts counts() const { return counts_; }

 private:
  ReferenceView& Entry(int i) const;
  EncodedView Encode(const ReferenceView& v) const;

  ReferenceViewStoreOptions options_;
  // The views (depth and planes empty while only encoded), their encodings (empty while a
  // decoded view has changed since), and when each was last used (Trim evicts the oldest).
  mutable std::vector<ReferenceView> views_;
  mutable std::vector<EncodedView> encoded_;
  mutable std::vector<uint64_t> last_use_;
  mutable uint64_t clock_ = 0;
  mutable Counts counts_;
};

/// `view`'s depth (key "") and planes encoded with `codec`.
EncodedView EncodeView(const ReferenceView& view, const PlaneCodecOptions& codec);
/// The depth and planes of `encoded` into `view` (camera as given). Throws std::runtime_error
/// naming the plane if its bytes are not an encoding of the camera's size.
void DecodeInto(const EncodedView& encoded, ReferenceView& view);

}  // namespace novelty::views
