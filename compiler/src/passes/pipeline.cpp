// The pass list, in order. Add a pass here and nowhere else.
#include "sdfc/passes/passes.hpp"

namespace sdfc::passes {

const std::vector<PassInfo>& pipeline() {
  static const std::vector<PassInfo> list = {
      {"verify", verify},
      {"fold_constants", fold_constants},
      {"canonicalise", canonicalise},
      {"cse", cse},
      {"eliminate_dead", eliminate_dead},
      {"infer_properties", infer_properties},
      {"insert_bounding_volumes", insert_bounding_volumes},
  };
  return list;
}

ir::Module run_pipeline(ir::Module m, const PassObserver& after) {
  for (const auto& pass : pipeline()) {
    m = pass.run(std::move(m));
    if (after) after(pass.name, m);
  }
  return m;
}

}  // namespace sdfc::passes
