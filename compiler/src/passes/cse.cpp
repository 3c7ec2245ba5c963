// cse: common-subexpression elimination. Rebuilding through the hash-consing
// Builder gives equal subtrees one node (after canonicalise has made equal
// things look equal) and leaves unreachable nodes behind.
#include "rewrite.hpp"
#include "sdfc/passes/passes.hpp"

namespace sdfc::passes {

ir::Module cse(ir::Module m) {
  return detail::rewrite(std::move(m), [](ir::Builder& b, const ir::Node& n, std::vector<ir::NodeId> kids) {
    return b.copy(n, std::move(kids));
  });
}

}  // namespace sdfc::passes
