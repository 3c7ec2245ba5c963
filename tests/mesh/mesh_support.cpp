#include "mesh_support.hpp"

#include "sdfc/codegen/emit_mesh_kernels.hpp"
#include "sdfc_test_support.hpp"

namespace sdfc::test {

Meshed mesh_scene(const std::string& yaml, int resolution, std::optional<cli::Region> bounds, bool colour, bool dense,
                  double adaptivity) {
  Meshed r{compile_text(yaml), {}, {}, {}};
  r.grid = cli::make_grid(bounds ? *bounds : cli::scene_region(r.module), resolution, 0);
  r.grid.iso = cli::default_iso(r.module, r.grid.voxel);
  codegen::EmittedKernel k = codegen::emit_mesh_kernels(r.module, 16);
  sdfrt::mesh::Sampler sampler(device(), k.source, 16);
  sdfrt::mesh::MesherOptions opt;
  opt.colour = colour;
  opt.dense = dense;
  opt.adaptivity = adaptivity;
  opt.gamma = r.module.plan.march.gamma;
  r.mesh = sdfrt::mesh::make_mesh(sampler, r.grid, opt, &r.stats);
  return r;
}

}  // namespace sdfc::test
