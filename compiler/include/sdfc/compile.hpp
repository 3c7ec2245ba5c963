#pragma once
// The whole front half in one call: file -> AST -> IR -> passes -> kernel.
#include <string>
#include <vector>

#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/ir/module.hpp"
#include "sdfc/passes/passes.hpp"
#include "sdfc/source/source_value.hpp"

namespace sdfc {

struct CompileTimings {
  double parse_ms = 0, lower_ms = 0, passes_ms = 0, emit_ms = 0;
  std::vector<passes::PassTiming> per_pass;
};

// Loads a scene file and applies --set overrides.
SourceValue load_scene_source(const std::string& path, const std::vector<std::string>& overrides);
// AST -> optimised module (runs the pass pipeline).
ir::Module build_module(const SourceValue& doc, const std::string& source_name,
                        const passes::PassObserver& after = {}, CompileTimings* t = nullptr);

}  // namespace sdfc
