#pragma once
// The functions expressions may call, with their arity, their value on the
// CPU and their OpenCL spelling. One table serves the parser, the evaluator
// and the emitter.
#include <string_view>
#include <vector>

namespace sdfc::expr {

struct Function {
  std::string_view name;
  int arity;
  double (*eval)(const double* args);
  std::string_view opencl;  // builtin name in OpenCL C
  bool internal = false;     // made by derivative(), not writable in a scene
};

const std::vector<Function>& functions();
const Function* find_function(std::string_view name);

}  // namespace sdfc::expr
