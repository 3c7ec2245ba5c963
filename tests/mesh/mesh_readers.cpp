#include "mesh_readers.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "test_files.hpp"

namespace sdfc::test {

using sdfrt::mesh::Mesh;
using sdfrt::mesh::Vec3f;

namespace {

template <typename T>
T take(const std::string& s, size_t& at) {
  if (at + sizeof(T) > s.size()) throw std::runtime_error("mesh file ends early");
  T v;
  std::memcpy(&v, s.data() + at, sizeof v);
  at += sizeof v;
  return v;
}

}  // namespace

Mesh read_stl(const std::string& path) {
  std::string s = read_text_file(path);
  size_t at = 80;
  auto count = take<std::uint32_t>(s, at);
  if (s.size() != 84 + 50 * size_t(count)) throw std::runtime_error("STL size does not match its triangle count");
  Mesh m;
  std::map<Vec3f, std::uint32_t> ids;
  for (std::uint32_t t = 0; t < count; ++t) {
    at += 12;  // facet normal
    sdfrt::mesh::Tri tri;
    for (int v = 0; v < 3; ++v) {
      Vec3f p{take<float>(s, at), take<float>(s, at), take<float>(s, at)};
      auto [it, fresh] = ids.emplace(p, std::uint32_t(m.vertices.size()));
      if (fresh) m.vertices.push_back(p);
      tri[v] = it->second;
    }
    at += 2;
    m.triangles.push_back(tri);
  }
  return m;
}

Mesh read_obj(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  Mesh m;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "v") {
      Vec3f p;
      ls >> p[0] >> p[1] >> p[2];
      m.vertices.push_back(p);
      double r, g, b;
      if (ls >> r >> g >> b)
        m.colours.push_back({std::uint8_t(std::lround(r * 255)), std::uint8_t(std::lround(g * 255)), std::uint8_t(std::lround(b * 255))});
    } else if (tag == "f") {
      sdfrt::mesh::Tri t;
      ls >> t[0] >> t[1] >> t[2];
      for (auto& i : t) i -= 1;
      m.triangles.push_back(t);
    }
  }
  return m;
}

Mesh read_ply(const std::string& path) {
  std::string s = read_text_file(path);
  size_t end = s.find("end_header\n");
  if (s.rfind("ply\nformat binary_little_endian 1.0\n", 0) != 0 || end == std::string::npos)
    throw std::runtime_error("not a binary little-endian PLY");
  std::istringstream header(s.substr(0, end));
  size_t vertices = 0, faces = 0;
  bool colour = false;
  std::string line;
  while (std::getline(header, line)) {
    std::istringstream ls(line);
    std::string a, b, c;
    ls >> a >> b >> c;
    if (a == "element" && b == "vertex") vertices = std::stoul(c);
    if (a == "element" && b == "face") faces = std::stoul(c);
    if (a == "property" && c == "red") colour = true;
  }
  size_t at = end + 11;
  Mesh m;
  for (size_t i = 0; i < vertices; ++i) {
    m.vertices.push_back({take<float>(s, at), take<float>(s, at), take<float>(s, at)});
    if (colour) m.colours.push_back({take<std::uint8_t>(s, at), take<std::uint8_t>(s, at), take<std::uint8_t>(s, at)});
  }
  for (size_t i = 0; i < faces; ++i) {
    if (take<std::uint8_t>(s, at) != 3) throw std::runtime_error("PLY face is not a triangle");
    m.triangles.push_back({std::uint32_t(take<std::int32_t>(s, at)), std::uint32_t(take<std::int32_t>(s, at)),
                           std::uint32_t(take<std::int32_t>(s, at))});
  }
  if (at != s.size()) throw std::runtime_error("PLY has bytes after its faces");
  return m;
}

}  // namespace sdfc::test
