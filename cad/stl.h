// STL of a triangle mesh: binary (default) or ASCII. The mesh is indexed so that its closedness can
// be checked (every edge shared by exactly two triangles, in opposite directions).
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace camopt::cad {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;    ///< [mm]
  std::vector<std::array<int, 3>> triangles;  ///< counter-clockwise seen from outside
};

/// Binary STL (80-byte header naming `solid_name`, little-endian float32 records).
std::string BinaryStl(const TriangleMesh& mesh, const std::string& solid_name);

/// ASCII STL.
std::string AsciiStl(const TriangleMesh& mesh, const std::string& solid_name);

/// Edges used by one triangle only (free edges) and edges used twice in the same direction
/// (inconsistent orientation) or more than twice; all zero for a closed, consistently oriented
/// solid.
struct EdgeCheck {
  long free_edges = 0, misoriented_edges = 0, overused_edges = 0;
};
EdgeCheck CheckEdges(const TriangleMesh& mesh);

}  // namespace camopt::cad
