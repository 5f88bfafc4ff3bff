// Ray-traced camera images of a RayScene: RGB8 with Phong shading (eq. 2.26), hard and soft
// shadows, mirror reflection on metal, refraction on glass, sensor noise and gamma; plus depth
// (float metres along the optical axis, 0 where nothing is hit) and an object-id image.
// Multi-threaded over image rows and bit-identical for a given seed whatever the thread count.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>

#include "core/pinhole_camera.h"
#include "sim/render/lighting.h"
#include "sim/render/ray_scene.h"

namespace novelty::sim {

struct RenderOptions {
  /// Display gamma: 8-bit value = 255 · (exposure · radiance)^(1/gamma). 2.2 as sRGB-like cameras.
  double gamma = 2.2;
  /// Scale from linear radiance to the sensor's full scale (1 = radiance 1 saturates).
  double exposure = 1.0;
  /// Standard deviation of additive Gaussian sensor noise, in 8-bit levels (0 = none).
  double noise_sigma = 1.0;
  /// Seed of the sensor noise and the soft-shadow sampling; with `frame`, fixes every random draw.
  std::uint64_t seed = 0;
  std::uint64_t frame = 0;
  /// n: the colour of a pixel is the mean radiance of an n × n grid of rays over the pixel's
  /// area, as a real sensor integrates light over its pixels. 1 = one ray through the centre
  /// (fast, but hard texture edges alias, which costs stereo matching sub-pixel precision).
  /// Depth and ids always come from the centre ray.
  int pixel_samples = 1;
  /// Shadow rays per area lamp (radius > 0); point lamps use one.
  int soft_shadow_samples = 16;
  /// Reflection/refraction depth for metal and glass.
  int max_bounces = 6;
  /// Worker threads; 0 = one per hardware core.
  int threads = 0;
  /// Colour of rays that leave the scene.
  Eigen::Vector3f background{0.0f, 0.0f, 0.0f};
};

struct RenderedFrame {
  cv::Mat rgb;    ///< CV_8UC3, R G B
  cv::Mat depth;  ///< CV_32FC1, metres along camera +Z; 0 = no surface
  cv::Mat ids;    ///< CV_32SC1, object id of the first surface; -1 = none
};

/// Renders the scene seen by `camera` at `T_world_cam`. Throws std::invalid_argument for a bad
/// camera or a pose that is not a rigid transform.
RenderedFrame Render(const RayScene& scene, const Lighting& lighting,
                     const core::PinholeCamera& camera, const Eigen::Isometry3d& T_world_cam,
                     const RenderOptions& options = {});

/// Only the object-id image (first surface per pixel, -1 = none): for ground-truth masks.
cv::Mat RenderIds(const RayScene& scene, const core::PinholeCamera& camera,
                  const Eigen::Isometry3d& T_world_cam, int threads = 0);

/// Linear radiance leaving the first surface along a ray (no noise, no gamma): the shading model
/// itself, for tests against closed forms. Returns `background` if nothing is hit.
Eigen::Vector3f TraceRadiance(const RayScene& scene, const Lighting& lighting,
                              const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                              const RenderOptions& options, std::uint64_t pixel_index = 0);

}  // namespace novelty::sim
