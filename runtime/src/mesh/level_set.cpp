// LevelSet as every program sees it: the OpenVDB implementation lives in
// the module libsdfc_openvdb.so, opened on the first mesh.
#include <sdfrt/mesh/level_set.hpp>

#include <string>

#include "loading/dynamic_library.hpp"
#include "mesh/level_set_backend.hpp"

namespace sdfrt::mesh {
namespace {

using Entry = decltype(&sdfc_openvdb_level_set);

Entry load_entry() {
  const std::string purpose = "making a mesh";
  void* lib = open_library(sdfc_module_path(SDFC_OPENVDB_MODULE), purpose);
  return reinterpret_cast<Entry>(library_symbol(lib, SDFC_OPENVDB_ENTRY, purpose));
}

// Opened once (a failed open is tried again by the next mesh).
Entry openvdb_entry() {
  static const Entry entry = load_entry();
  return entry;
}

}  // namespace

struct LevelSet::Impl {
  std::unique_ptr<LevelSetBackend> backend;
};

LevelSet::LevelSet(const GridSpec& grid) : impl_(std::make_unique<Impl>()) {
  impl_->backend.reset(openvdb_entry()(&grid));
}

LevelSet::~LevelSet() = default;

void LevelSet::add_block(const std::array<int, 3>& block, const float* samples) {
  impl_->backend->add_block(block, samples);
}
std::size_t LevelSet::blocks() const { return impl_->backend->blocks(); }
std::size_t LevelSet::memory_bytes() const { return impl_->backend->memory_bytes(); }
float LevelSet::min_value() const { return impl_->backend->min_value(); }
Mesh LevelSet::to_mesh(double adaptivity) { return impl_->backend->to_mesh(adaptivity); }

}  // namespace sdfrt::mesh
