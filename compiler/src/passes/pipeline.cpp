// The pass list, in order. Add a pass here and nowhere else.
#include "sdfc/passes/passes.hpp"

#include <chrono>

namespace sdfc::passes {

const std::vector<PassInfo>& pipeline() {
  static const std::vector<PassInfo> list = {
      {"verify", verify},
      {"fold_constants", fold_constants},
      {"canonicalise", canonicalise},
      {"cse", cse},
      {"eliminate_dead", eliminate_dead},
      {"infer_properties", infer_properties},
      {"analyse", analyse},
      {"insert_bounding_volumes", insert_bounding_volumes},
      {"gather_object_sets", gather_object_sets},
  };
  return list;
}

ir::Module run_pipeline(ir::Module m, const PassObserver& after, std::vector<PassTiming>* timings) {
  for (const auto& pass : pipeline()) {
    auto t0 = std::chrono::steady_clock::now();
    m = pass.run(std::move(m));
    if (timings)
      timings->push_back({pass.name, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count()});
    if (after) after(pass.name, m);
  }
  return m;
}

}  // namespace sdfc::passes
