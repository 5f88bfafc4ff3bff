// A synthetic object put into real RGB-D frames as if it had stood there: rendered by the
// simulator's ray tracer from each frame's camera pose and intrinsics, and pasted over the frame
// wherever its surface is nearer than what the frame's depth saw (or the depth is unknown), with
// its depth — so the real scene occludes it where it stands in front. Real recordings rarely come
// with something added at a known place; this gives them one, with its exact mask, to score
// novelty against (issue 51, item 6).
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"
#include "sim/render/lighting.h"
#include "sim/render/material.h"
#include "sim/render/ray_scene.h"
#include "sim/render/renderer.h"

namespace novelty::sim {

struct InsertedBoxOptions {
  Eigen::Vector3d size{0.30, 0.30, 0.30};  ///< edge lengths (m)
  /// Where it stands: world ← box centre. ObjectInserter::StandInFrontOf picks one from a frame.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  /// A coloured checkerboard (8 cells a face): texture a novelty detector can see, whatever the
  /// room's colours.
  Material material = [] {
    Material m;
    m.diffuse = {0.85f, 0.55f, 0.10f};
    m.texture.kind = Texture::Kind::kChecker;
    m.texture.second = {0.10f, 0.25f, 0.65f};
    m.texture.cells = 4.0f;
    return m;
  }();
  /// Lit by ambient light and a lamp at the camera (set per frame): no shadows cast on the real
  /// scene, which the frame's own light would not show either.
  Eigen::Vector3f ambient{0.35f, 0.35f, 0.35f};
  Eigen::Vector3f lamp{0.6f, 0.6f, 0.6f};  ///< the camera lamp's irradiance at 1 m
  double noise_sigma = 1.5;                ///< sensor noise on the box's pixels (8-bit levels)
};

class ObjectInserter {
 public:
  /// Throws std::invalid_argument for a size that is not positive and finite or a pose that is
  /// not rigid.
  explicit ObjectInserter(const InsertedBoxOptions& options);

  /// Pastes the box into `rgb` (CV_8UC3 R G B) and `depth` (CV_32FC1 m, 0 or NaN unknown) seen
  /// by `camera` at `T_world_cam`; returns where it is now seen (CV_8UC1, 255), empty of 255 when
  /// it is out of view or hidden. `frame` seeds the noise.
  cv::Mat Insert(cv::Mat& rgb, cv::Mat& depth, const core::PinholeCamera& camera,
                 const Eigen::Isometry3d& T_world_cam, int frame) const;

  /// A pose `standoff` metres in front of the surface at the centre of `depth` as seen from
  /// `T_world_cam` (the median depth of the central 21×21 pixels), the box's axes the camera's,
  /// so that a face looks at that camera. Throws std::invalid_argument when the centre has no
  /// depth or the box would not be in front of the camera.
  static Eigen::Isometry3d StandInFrontOf(const cv::Mat& depth, const core::PinholeCamera& camera,
                                          const Eigen::Isometry3d& T_world_cam, double standoff,
                                          const Eigen::Vector3d& size);

 private:
  InsertedBoxOptions options_;
  RayScene scene_;
};

}  // namespace novelty::sim
