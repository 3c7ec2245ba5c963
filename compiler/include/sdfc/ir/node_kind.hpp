#pragma once
#include <cstdint>
#include <string_view>
#include <vector>

namespace sdfc::ir {

enum class Kind : uint16_t {
#define NODE(e, name, cat, arity, params, fn) e,
#include "sdfc/ir/kind_table.def"  // generated: compiler/kinds.cmake
#undef NODE
};

enum class Category { Primitive, Fractal, Transform, Combinator, Material };

struct KindInfo {
  Kind kind;
  std::string_view name;
  Category category;
  int arity;  // 0 leaf, 1 unary, -1 n-ary
  std::vector<std::string_view> params;
  std::string_view stdlib_function;  // empty when emitted inline
};

const KindInfo& info(Kind k);
const std::vector<KindInfo>& all_kinds();
// Order of the children does not matter: union, intersection, and smooth
// union/intersection of two children (smooth blends are not associative).
bool is_commutative(Kind k);

}  // namespace sdfc::ir
