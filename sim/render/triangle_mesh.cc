#include "sim/render/triangle_mesh.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace novelty::sim {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Adds a quad (a, b, c, d counter-clockwise) with a flat normal and uv corners (0,0)…(1,1).
void AddQuad(TriangleMesh& m, const Eigen::Vector3f& a, const Eigen::Vector3f& b,
             const Eigen::Vector3f& c, const Eigen::Vector3f& d) {
  const int base = static_cast<int>(m.vertices.size());
  const Eigen::Vector3f n = (b - a).cross(d - a).normalized();
  m.vertices.insert(m.vertices.end(), {a, b, c, d});
  m.normals.insert(m.normals.end(), 4, n);
  m.uvs.insert(m.uvs.end(), {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  m.triangles.push_back({base, base + 1, base + 2});
  m.triangles.push_back({base, base + 2, base + 3});
}

// A surface of revolution around z: profile points (r, z) with outward normals (nr, nz); the
// grid of `segments` × profile is stitched into triangles. Used by cylinder, cup, plate, sphere.
struct ProfilePoint {
  double r, z, nr, nz, v;  // v: texture coordinate along the profile
};

void AddRevolution(TriangleMesh& m, const std::vector<ProfilePoint>& profile, int segments) {
  const int base = static_cast<int>(m.vertices.size());
  const int cols = segments + 1;  // duplicate seam column for continuous uv
  for (const ProfilePoint& p : profile) {
    for (int s = 0; s < cols; ++s) {
      const double phi = 2.0 * kPi * s / segments;
      const double c = std::cos(phi), sn = std::sin(phi);
      m.vertices.emplace_back(float(p.r * c), float(p.r * sn), float(p.z));
      m.normals.push_back(
          Eigen::Vector3f(float(p.nr * c), float(p.nr * sn), float(p.nz)).normalized());
      m.uvs.emplace_back(float(double(s) / segments), float(p.v));
    }
  }
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
    for (int s = 0; s < segments; ++s) {
      const int a = base + int(i) * cols + s, b = a + 1, c = a + cols + 1, d = a + cols;
      // Profile runs bottom → top (or outer → inner); order keeps the normal side outward.
      m.triangles.push_back({a, b, c});
      m.triangles.push_back({a, c, d});
    }
  }
}

// A flat disc at height z facing up (+1) or down (-1).
void AddDisc(TriangleMesh& m, double radius, double z, int facing, int segments) {
  const int centre = static_cast<int>(m.vertices.size());
  const Eigen::Vector3f n(0, 0, float(facing));
  m.vertices.emplace_back(0.f, 0.f, float(z));
  m.normals.push_back(n);
  m.uvs.emplace_back(0.5f, 0.5f);
  for (int s = 0; s <= segments; ++s) {
    const double phi = 2.0 * kPi * s / segments;
    m.vertices.emplace_back(float(radius * std::cos(phi)), float(radius * std::sin(phi)), float(z));
    m.normals.push_back(n);
    m.uvs.emplace_back(float(0.5 + 0.5 * std::cos(phi)), float(0.5 + 0.5 * std::sin(phi)));
  }
  for (int s = 0; s < segments; ++s) {
    const int a = centre + 1 + s, b = a + 1;
    if (facing > 0) {
      m.triangles.push_back({centre, a, b});
    } else {
      m.triangles.push_back({centre, b, a});
    }
  }
}

}  // namespace

void TriangleMesh::Append(const TriangleMesh& other) {
  const int base = static_cast<int>(vertices.size());
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  normals.insert(normals.end(), other.normals.begin(), other.normals.end());
  uvs.insert(uvs.end(), other.uvs.begin(), other.uvs.end());
  for (const Eigen::Vector3i& t : other.triangles) triangles.push_back(t.array() + base);
}

TriangleMesh TriangleMesh::Transformed(const Eigen::Isometry3d& pose) const {
  TriangleMesh out = *this;
  const Eigen::Isometry3f p = pose.cast<float>();
  for (Eigen::Vector3f& v : out.vertices) v = p * v;
  for (Eigen::Vector3f& n : out.normals) n = p.linear() * n;
  return out;
}

void TriangleMesh::Check(const char* what) const {
  if (normals.size() != vertices.size() || uvs.size() != vertices.size()) {
    throw std::invalid_argument(std::string(what) + ": " + std::to_string(vertices.size()) +
                                " vertices but " + std::to_string(normals.size()) +
                                " normals and " + std::to_string(uvs.size()) + " uvs");
  }
  const int n = static_cast<int>(vertices.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    if ((triangles[i].array() < 0).any() || (triangles[i].array() >= n).any()) {
      throw std::invalid_argument(std::string(what) + ": triangle " + std::to_string(i) +
                                  " indexes a vertex outside [0, " + std::to_string(n) + ")");
    }
  }
}

TriangleMesh MakeBox(const Eigen::Vector3d& size) {
  const Eigen::Vector3f h = (0.5 * size).cast<float>();
  auto P = [&](float sx, float sy, float sz) {
    return Eigen::Vector3f(sx * h.x(), sy * h.y(), sz * h.z());
  };
  TriangleMesh m;
  AddQuad(m, P(-1, -1, 1), P(1, -1, 1), P(1, 1, 1), P(-1, 1, 1));      // top
  AddQuad(m, P(-1, 1, -1), P(1, 1, -1), P(1, -1, -1), P(-1, -1, -1));  // bottom
  AddQuad(m, P(1, -1, -1), P(1, 1, -1), P(1, 1, 1), P(1, -1, 1));      // +x
  AddQuad(m, P(-1, 1, -1), P(-1, -1, -1), P(-1, -1, 1), P(-1, 1, 1));  // -x
  AddQuad(m, P(1, 1, -1), P(-1, 1, -1), P(-1, 1, 1), P(1, 1, 1));      // +y
  AddQuad(m, P(-1, -1, -1), P(1, -1, -1), P(1, -1, 1), P(-1, -1, 1));  // -y
  return m;
}

TriangleMesh MakePlane(double size_x, double size_y, double tile) {
  const float hx = float(size_x / 2), hy = float(size_y / 2);
  TriangleMesh m;
  AddQuad(m, {-hx, -hy, 0}, {hx, -hy, 0}, {hx, hy, 0}, {-hx, hy, 0});
  for (Eigen::Vector2f& uv : m.uvs) {
    uv = Eigen::Vector2f(uv.x() * float(size_x / tile), uv.y() * float(size_y / tile));
  }
  return m;
}

TriangleMesh MakeSphere(double radius, int segments, int rings) {
  std::vector<ProfilePoint> profile;
  for (int i = 0; i <= rings; ++i) {
    const double theta = -kPi / 2 + kPi * i / rings;  // bottom pole → top pole
    const double c = std::cos(theta), s = std::sin(theta);
    profile.push_back({radius * c, radius * s, c, s, double(i) / rings});
  }
  TriangleMesh m;
  AddRevolution(m, profile, segments);
  return m;
}

TriangleMesh MakeCylinder(double radius, double height, int segments) {
  const double h = height / 2;
  TriangleMesh m;
  AddRevolution(m, {{radius, -h, 1, 0, 0}, {radius, h, 1, 0, 1}}, segments);
  AddDisc(m, radius, h, +1, segments);
  AddDisc(m, radius, -h, -1, segments);
  return m;
}

TriangleMesh MakeCup(double radius, double height, double wall, int segments) {
  const double h = height / 2, ri = radius - wall;
  TriangleMesh m;
  // Outer wall (bottom → top), rim (outer → inner), inner wall (top → bottom, normal inward).
  AddRevolution(m, {{radius, -h, 1, 0, 0}, {radius, h, 1, 0, 1}}, segments);
  AddRevolution(m, {{radius, h, 0, 1, 0}, {ri, h, 0, 1, 1}}, segments);
  AddRevolution(m, {{ri, h, -1, 0, 0}, {ri, -h + wall, -1, 0, 1}}, segments);
  AddDisc(m, ri, -h + wall, +1, segments);  // inner bottom
  AddDisc(m, radius, -h, -1, segments);     // outer bottom
  return m;
}

TriangleMesh MakePlate(double radius, double thickness, int segments) {
  const double h = thickness / 2, rim = 0.15 * radius;
  TriangleMesh m;
  // A shallow rim rising outward around a flat well; profile outer → inner so it faces up.
  AddRevolution(m, {{radius, h + rim * 0.3, -0.3, 1, 1}, {radius - rim, h, -0.3, 1, 0}}, segments);
  AddRevolution(m, {{radius, -h, 1, 0, 0}, {radius, h + rim * 0.3, 1, 0, 1}}, segments);
  AddDisc(m, radius - rim, h, +1, segments);
  AddDisc(m, radius, -h, -1, segments);
  return m;
}

}  // namespace novelty::sim
