// Light sources of the simulated rooms: coloured point lamps (on tripods, on the ceiling) that
// may be area lamps with soft shadows, daylight through a window as a directional light, and
// ambient light. Radiometry is linear; the camera model maps it to 8-bit values.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace novelty::sim {

struct PointLight {
  Eigen::Vector3d position{0.0, 0.0, 2.5};
  /// RGB intensity: irradiance on a surface facing the lamp at 1 m (inverse-square falloff).
  Eigen::Vector3f intensity{1.0f, 1.0f, 1.0f};
  /// Radius of a spherical area lamp in metres; 0 = point lamp with hard shadows.
  double radius = 0.0;
};

struct DirectionalLight {
  Eigen::Vector3d direction{0.0, 0.0, -1.0};  ///< direction the light travels (unit)
  Eigen::Vector3f irradiance{0.5f, 0.5f, 0.5f};
};

struct Lighting {
  Eigen::Vector3f ambient{0.05f, 0.05f, 0.05f};  ///< irradiance reaching every surface
  std::vector<PointLight> points;
  std::vector<DirectionalLight> directional;
};

}  // namespace novelty::sim
