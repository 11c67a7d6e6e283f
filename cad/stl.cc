#include "cad/stl.h"

#include <Eigen/Geometry>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <sstream>
#include <utility>

namespace camopt::cad {

namespace {

Eigen::Vector3d Normal(const TriangleMesh& m, const std::array<int, 3>& t) {
  const Eigen::Vector3d n =
      (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]);
  const double len = n.norm();
  return len > 0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::Zero();
}

// A float in little-endian byte order (the STL's, on any host) at out[0..3].
char* PutFloat(char* out, double v) {
  const float f = static_cast<float>(v);
  std::uint32_t bits;
  std::memcpy(&bits, &f, 4);
  if constexpr (std::endian::native == std::endian::little) {
    std::memcpy(out, &bits, 4);
  } else {
    for (int i = 0; i < 4; ++i) out[i] = static_cast<char>((bits >> (8 * i)) & 0xff);
  }
  return out + 4;
}

}  // namespace

std::string BinaryStl(const TriangleMesh& mesh, const std::string& solid_name) {
  std::string header = "camopt binary STL, mm: " + solid_name;
  header.resize(80, ' ');
  if (header.compare(0, 5, "solid") == 0) header[0] = 'S';  // never mistaken for ASCII
  const std::uint32_t n = static_cast<std::uint32_t>(mesh.triangles.size());
  // 80-byte header, the count, and 50 bytes per triangle (normal, 3 vertices, attribute 0).
  std::string s(84 + 50 * size_t(n), '\0');
  std::memcpy(s.data(), header.data(), 80);
  for (int i = 0; i < 4; ++i) s[80 + i] = static_cast<char>((n >> (8 * i)) & 0xff);
  char* out = s.data() + 84;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d nn = Normal(mesh, t);
    for (int k = 0; k < 3; ++k) out = PutFloat(out, nn[k]);
    for (int v = 0; v < 3; ++v)
      for (int k = 0; k < 3; ++k) out = PutFloat(out, mesh.vertices[t[v]][k]);
    out += 2;  // attribute byte count 0
  }
  return s;
}

std::string AsciiStl(const TriangleMesh& mesh, const std::string& name) {
  // "solid NAME" is one line and its name one token for some readers: control bytes and
  // spaces become '_' (a study name with a line break broke the file).
  std::string solid_name = name;
  for (char& c : solid_name)
    if (static_cast<unsigned char>(c) <= 0x20 || c == 0x7f) c = '_';
  std::ostringstream os;
  char buf[160];
  os << "solid " << solid_name << "\n";
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d nn = Normal(mesh, t);
    std::snprintf(buf, sizeof buf, "facet normal %.7g %.7g %.7g\n outer loop\n", nn.x(), nn.y(), nn.z());
    os << buf;
    for (int v = 0; v < 3; ++v) {
      const Eigen::Vector3d& p = mesh.vertices[t[v]];
      std::snprintf(buf, sizeof buf, "  vertex %.9g %.9g %.9g\n", p.x(), p.y(), p.z());
      os << buf;
    }
    os << " endloop\nendfacet\n";
  }
  os << "endsolid " << solid_name << "\n";
  return os.str();
}

EdgeCheck CheckEdges(const TriangleMesh& mesh) {
  // Directed edge counts, keyed by vertex index pairs.
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  EdgeCheck c;
  for (const auto& [e, n] : directed) {
    const auto it = directed.find({e.second, e.first});
    const int back = it == directed.end() ? 0 : it->second;
    if (e.first > e.second && back > 0) continue;  // count each undirected edge once
    if (n + back == 1) ++c.free_edges;
    else if (n + back > 2) ++c.overused_edges;
    else if (n != 1 || back != 1) ++c.misoriented_edges;
  }
  return c;
}

}  // namespace camopt::cad
