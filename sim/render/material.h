// Surface materials of the simulated scenes: Phong diffuse + specular (eq. 2.26: k_d, k_s, n),
// procedural and image textures, mirror-like metal and refracting glass.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace novelty::sim {

/// Where the diffuse colour comes from. Texture coordinates are the mesh's per-vertex uvs.
struct Texture {
  enum class Kind {
    kNone,     ///< uniform colour Material::diffuse
    kChecker,  ///< squares of `diffuse` and `second` colour, `cells` per uv unit
    kStripes,  ///< stripes along u (a patterned tablecloth)
    kImage,    ///< `image` (CV_8UC3, RGB) tiled over uv ∈ [0,1]², bilinear
  };
  Kind kind = Kind::kNone;
  Eigen::Vector3f second{0.1f, 0.1f, 0.1f};
  float cells = 8.0f;
  cv::Mat image;
};

struct Material {
  enum class Kind {
    kPhong,  ///< diffuse + Phong specular lobe
    kMetal,  ///< Phong plus a mirror reflection weighted by `reflectivity`
    kGlass,  ///< refraction (index `ior`) and Fresnel reflection, tinted by `diffuse`
  };
  Kind kind = Kind::kPhong;
  Eigen::Vector3f diffuse{0.6f, 0.6f, 0.6f};  ///< k_d per RGB channel, 0…1 (albedo)
  float specular = 0.0f;                      ///< k_s, 0…1
  float shininess = 20.0f;                    ///< Phong exponent n
  float reflectivity = 0.0f;                  ///< kMetal: mirror weight 0…1
  float ior = 1.5f;                           ///< kGlass: index of refraction
  Texture texture;

  /// k_d at texture coordinate uv.
  Eigen::Vector3f DiffuseAt(const Eigen::Vector2f& uv) const;
};

}  // namespace novelty::sim
