#pragma once
// What a printer's slicer needs of a mesh, checked: every edge shared by
// exactly two triangles, in opposite directions (watertight, consistently
// oriented); and its Euler characteristic, parts, volume and area.
#include <sdfrt/mesh/mesh.hpp>

#include <cstddef>
#include <cstdint>

namespace sdfrt::mesh {

struct Topology {
  std::size_t edges = 0;
  std::size_t open_edges = 0;        // used by one triangle
  std::size_t overshared_edges = 0;  // used by three or more
  std::size_t misoriented_edges = 0; // two triangles running it the same way
  std::size_t degenerate_triangles = 0;  // a repeated vertex
  std::size_t parts = 0;             // connected components
  std::int64_t euler = 0;            // V - E + F
  bool watertight() const { return open_edges == 0 && overshared_edges == 0; }
  bool oriented() const { return misoriented_edges == 0; }
};
Topology check_topology(const Mesh& mesh);

double volume(const Mesh& mesh);  // signed: positive when wound outwards
double area(const Mesh& mesh);

}  // namespace sdfrt::mesh
