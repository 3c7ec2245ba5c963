#pragma once
// What a description's `lower` reads the scene with: the node's key and
// body, located errors, and the builder.
#include <initializer_list>
#include <string>
#include <string_view>

#include "sdfc/frontend/value_reader.hpp"
#include "sdfc/kinds/description.hpp"

namespace sdfc::kinds {

class Lowering {
 public:
  Lowering(const Description& d, frontend::ValueReader& r, ir::Builder& b, const SourceValue& key,
           const SourceValue& body)
      : d_(d), r_(r), b_(b), key_(key), body_(body) {}

  // The body as a map with these keys (unknown ones are reported).
  frontend::MapReader map(std::initializer_list<std::string_view> allowed) {
    return frontend::MapReader(r_, body_, key_.scalar, allowed);
  }
  // An error at `key` of m (at the body when the key is absent); make()
  // then returns kNoNode.
  void fail(const frontend::MapReader& m, std::string_view key, const std::string& msg);
  // An error that keeps the node (the rest of the scene is still checked).
  void report(const frontend::MapReader& m, std::string_view key, const std::string& msg);
  template <class P>
  ir::NodeId make(const P& params) {
    return make_node(params_of(params));
  }
  // Parameters that may be expressions of time, in the order of Node::params.
  ir::NodeId make_animated(const std::vector<frontend::Param>& params);
  // For lowerings that read more than one map (a fractal's nested steps, a formula's chain) or
  // make a node of a sibling kind (mandelbulb with julia: a Juliabulb).
  frontend::ValueReader& reader() { return r_; }
  ir::Builder& builder() { return b_; }
  const SourceValue& body() const { return body_; }
  const SourceLoc& at() const { return key_.loc; }
  const SourceValue& key() const { return key_; }  // a preset's node: its name

 private:
  ir::NodeId make_node(std::vector<double> params);
  const Description& d_;
  frontend::ValueReader& r_;
  ir::Builder& b_;
  const SourceValue& key_;
  const SourceValue& body_;
  bool failed_ = false;
};

}  // namespace sdfc::kinds
