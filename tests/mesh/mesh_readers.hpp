#pragma once
// Small independent readers for the three mesh formats sdfc writes, so the
// tests check the files themselves, not the writer's own view of them.
#include <sdfrt/mesh/mesh.hpp>

#include <string>

namespace sdfc::test {

// STL is a triangle soup: vertices come back welded where they are
// bit-identical (the writer writes each shared vertex the same way).
sdfrt::mesh::Mesh read_stl(const std::string& path);
sdfrt::mesh::Mesh read_obj(const std::string& path);  // "v x y z [r g b]" and "f a b c"
sdfrt::mesh::Mesh read_ply(const std::string& path);  // binary little-endian, float xyz, optional uchar rgb

}  // namespace sdfc::test
