#pragma once
// The stdlib split into functions. Each function in stdlib/*.cl starts with
//   //! fn NAME            its name
//   //! deps: A, B         stdlib functions it calls (optional)
//   //! after-scene        it calls scene_dist, so it goes after the scene code
//   //! class: exact|bound|estimate|helper
// The emitter asks for the functions a scene reaches and gets them with their
// dependencies, in dependency order, and nothing else.
#include <string>
#include <string_view>
#include <vector>

namespace sdfc::codegen {

struct StdlibFunction {
  std::string name;
  std::string file;
  std::vector<std::string> deps;
  std::string cls;
  bool after_scene = false;
  std::string text;  // the whole chunk, header comments included
};

class StdlibManifest {
 public:
  static const StdlibManifest& instance();  // parsed once from the embedded files
  const StdlibFunction* find(std::string_view name) const;
  const std::vector<StdlibFunction>& functions() const { return fns_; }
  // `roots` plus everything they depend on, dependencies first. Throws
  // std::logic_error for an unknown name (a compiler bug, not a user error).
  std::vector<const StdlibFunction*> closure(const std::vector<std::string>& roots) const;

 private:
  std::vector<StdlibFunction> fns_;
};

}  // namespace sdfc::codegen
