// Indexed triangle meshes with per-vertex normals and texture coordinates, and the primitive
// shapes the simulated rooms are built from (boxes, cylinders, spheres, planes, cups, plates).
// All primitives are centred on their local origin with z up (MRPT's convention), in metres.
#pragma once

#include <Eigen/Geometry>
#include <vector>

namespace novelty::sim {

struct TriangleMesh {
  std::vector<Eigen::Vector3f> vertices;
  std::vector<Eigen::Vector3f> normals;    ///< one unit normal per vertex (smooth shading)
  std::vector<Eigen::Vector2f> uvs;        ///< one texture coordinate per vertex
  std::vector<Eigen::Vector3i> triangles;  ///< counter-clockwise seen from outside

  /// Appends another mesh (indices shifted).
  void Append(const TriangleMesh& other);
  /// The mesh moved by a rigid transform (normals rotated).
  TriangleMesh Transformed(const Eigen::Isometry3d& pose) const;
  /// Throws std::invalid_argument naming `what` if sizes disagree or an index is out of range.
  void Check(const char* what) const;
};

/// Axis-aligned box with the given edge lengths; flat faces, each face's uv spans [0,1]².
TriangleMesh MakeBox(const Eigen::Vector3d& size);
/// Rectangle in the local xy plane facing +z; uv = (x, y) / tile (tile in metres per texture
/// repeat).
TriangleMesh MakePlane(double size_x, double size_y, double tile = 1.0);
/// UV sphere; smooth normals.
TriangleMesh MakeSphere(double radius, int segments = 48, int rings = 24);
/// Closed cylinder along z; smooth side, flat caps.
TriangleMesh MakeCylinder(double radius, double height, int segments = 48);
/// Open-top cup: outer and inner wall of a cylinder with a bottom, wall thickness given.
TriangleMesh MakeCup(double radius, double height, double wall = 0.004, int segments = 48);
/// Flat round plate (a thin cylinder with a rim), as the tin plate of 6.4.2.
TriangleMesh MakePlate(double radius, double thickness = 0.01, int segments = 64);

}  // namespace novelty::sim
