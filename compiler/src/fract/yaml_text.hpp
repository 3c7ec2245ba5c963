#pragma once
// Small helpers for writing the imported scene's YAML: numbers in the
// shortest form that reads back to the same double, vectors, and a node as
// a block of `key: value   # from` lines.
#include <string>
#include <vector>

#include "sdfc/fract/fract_params.hpp"

namespace sdfc::fract {

std::string num(double v);                // 0.1, 2, -1.5e-07
std::string vec(const Vec3& v);           // [x, y, z]
std::string vec(const std::vector<double>& v);

// One line of a node's body: `key: value`, with the Mandelbulber key it came from.
struct Field {
  std::string key, value, from;
};

// A geometry node: its kind key, its fields, modifiers (`translate`,
// `scale`) and, for combinators, children.
struct Node {
  std::string kind;
  std::string from;  // e.g. "formula_1 8 (Mandelbox)"
  std::vector<Field> fields;
  std::vector<Field> modifiers;
  std::vector<Node> children;  // union / intersection / difference
};

// Writes `node` as YAML at `indent` spaces (a list item when `item`).
void write_node(std::string& out, const Node& node, int indent, bool item);

// `key: value` padded so the comments line up, then `# from`.
std::string commented(const std::string& text, const std::string& from);

}  // namespace sdfc::fract
