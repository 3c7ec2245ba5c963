#include "sdfc/ir/node_kind.hpp"

#include <string>

namespace sdfc::ir {

namespace {
std::vector<std::string_view> split_params(std::string_view s) {
  std::vector<std::string_view> out;
  while (!s.empty()) {
    size_t c = s.find(',');
    out.push_back(s.substr(0, c));
    if (c == std::string_view::npos) break;
    s.remove_prefix(c + 1);
  }
  return out;
}
}  // namespace

const std::vector<KindInfo>& all_kinds() {
  static const std::vector<KindInfo> kinds = {
#define NODE(e, name, cat, arity, params, fn) {Kind::e, name, Category::cat, arity, split_params(params), fn},
#include "sdfc/ir/kind_table.def"  // generated: compiler/kinds.cmake
#undef NODE
  };
  return kinds;
}

const KindInfo& info(Kind k) { return all_kinds().at(static_cast<size_t>(k)); }

bool is_commutative(Kind k) {
  return k == Kind::Union || k == Kind::Intersection || k == Kind::SmoothUnion || k == Kind::SmoothIntersection;
}

}  // namespace sdfc::ir
