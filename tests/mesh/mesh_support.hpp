#pragma once
// Meshes a scene in-process through the same pieces `sdfc mesh` uses: the
// emitted mesh kernel on the test device, the narrow band, OpenVDB.
#include <sdfrt/mesh/mesher.hpp>
#include <sdfrt/mesh/topology.hpp>

#include <optional>
#include <string>

#include "mesh_region.hpp"
#include "sdfc/ir/module.hpp"

namespace sdfc::test {

struct Meshed {
  ir::Module module;
  sdfrt::mesh::GridSpec grid;
  sdfrt::mesh::Mesh mesh;
  sdfrt::mesh::MesherStats stats;
};

// bounds: the scene's inferred bounds when empty.
Meshed mesh_scene(const std::string& yaml, int resolution, std::optional<cli::Region> bounds = std::nullopt,
                  bool colour = false, bool dense = false, double adaptivity = 0);

}  // namespace sdfc::test
