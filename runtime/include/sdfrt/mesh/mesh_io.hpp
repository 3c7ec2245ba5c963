#pragma once
// Mesh files, each written through a temporary file and a rename: binary
// STL, OBJ (vertex colours as "v x y z r g b"), binary little-endian PLY
// (uchar red, green, blue per vertex).
#include <sdfrt/mesh/mesh.hpp>

#include <optional>
#include <string>

namespace sdfrt::mesh {

enum class Format { Stl, Obj, Ply };
// From the file name's extension (case-insensitive); nullopt when unknown.
std::optional<Format> format_for(const std::string& path);
bool holds_colour(Format f);  // STL has no vertex colours

// Throws IoError naming the path.
void write_mesh(const std::string& path, Format format, const Mesh& mesh);

}  // namespace sdfrt::mesh
