#pragma once
// Every pass is a free function Module -> Module in its own file; they run
// as one flat list in pipeline.cpp (Halide's Lower.cpp style).
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "sdfc/ir/module.hpp"

namespace sdfc::passes {

ir::Module verify(ir::Module m);              // structural checks; throws on a broken IR
ir::Module fold_constants(ir::Module m);      // merge/remove transforms, collapse one-child combinators
ir::Module canonicalise(ir::Module m);        // flatten nested unions, sort commutative children, transforms outward
ir::Module cse(ir::Module m);                 // rebuild through the hash-consing builder, drop unreachable nodes
ir::Module infer_properties(ir::Module m);    // bounds, distance class, Lipschitz constant, cost
ir::Module analyse(ir::Module m);             // what the emitters need: time, blends, traps, ray bounds
ir::Module insert_bounding_volumes(ir::Module m);  // box tests in front of expensive subtrees
ir::Module eliminate_dead(ir::Module m);      // unused materials, dark lights
ir::Module gather_object_sets(ir::Module m);  // large unions of spheres and boxes become data (sdfc/ir/object_set.hpp)

struct PassInfo {
  std::string_view name;
  ir::Module (*run)(ir::Module);
};
const std::vector<PassInfo>& pipeline();

// Runs the pipeline; after each pass calls `after(name, module)` if given
// and, if `timings` is given, appends (pass name, milliseconds).
using PassObserver = std::function<void(std::string_view, const ir::Module&)>;
struct PassTiming {
  std::string_view pass;
  double ms;
};
ir::Module run_pipeline(ir::Module m, const PassObserver& after = {}, std::vector<PassTiming>* timings = nullptr);

}  // namespace sdfc::passes
