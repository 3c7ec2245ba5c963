// Packets wider than OpenCL's vectors. OpenCL C stops at 16 lanes, but a
// CPU marching one 16-lane packet waits on each step's square roots and
// divisions: every step depends on the last. Two or four packets' worth of
// lanes in one work-item give the core independent work to overlap (the
// bench scene's frame: 105 ms at 16 lanes, 65 ms at 64). Wider packets are
// Clang vectors whose halves are OpenCL vectors, and every builtin the
// kernel calls gets an overload for them.
#include "wide_lanes.hpp"

#include <fmt/format.h>

#include <cctype>
#include <set>
#include <vector>

namespace sdfc::codegen::detail {
namespace {

// A builtin and the overloads a wide kernel needs of it. In a form, R is a
// lane vector (`real` at that width), M a lane mask and S the scalar; the
// first letter is the result. Only the forms OpenCL defines at 16 lanes
// appear, so a call that builds at 16 lanes builds when wider. `body` is
// the overload's body over Clang's own vector operations (a, b, c are the
// arguments) where they give OpenCL's result bit for bit; without one,
// the builtin applies to the two halves. A body keeps the kernel's IR one
// instruction per operation: PoCL built the Mandelbulb example 0.4 s
// faster than with the halves' extracts and inserts.
struct Form {
  const char* sig;
  const char* body = nullptr;
};
struct Builtin {
  const char* name;
  std::vector<Form> forms;
};

const std::vector<Builtin>& builtins() {
  static const std::vector<Builtin> table = [] {
    std::vector<Builtin> t;
    for (const char* f : {"sqrt", "rsqrt", "cbrt", "round", "rint", "sign", "sin", "cos", "tan", "asin", "acos",
                          "atan", "sinh", "cosh", "tanh", "asinh", "acosh", "atanh", "exp", "exp2", "exp10", "expm1",
                          "log", "log2", "log10", "log1p", "degrees", "radians", "native_sqrt", "native_rsqrt",
                          "native_recip", "native_sin", "native_cos", "native_tan", "native_exp", "native_exp2",
                          "native_log", "native_log2", "half_sqrt", "half_rsqrt", "half_recip"})
      t.push_back({f, {{"RR"}}});
    t.push_back({"fabs", {{"RR", "__builtin_elementwise_abs(a)"}}});
    t.push_back({"floor", {{"RR", "__builtin_elementwise_floor(a)"}}});
    t.push_back({"ceil", {{"RR", "__builtin_elementwise_ceil(a)"}}});
    t.push_back({"trunc", {{"RR", "__builtin_elementwise_trunc(a)"}}});
    for (const char* f : {"fmax", "max"})
      t.push_back({f, {{"RRR", "__builtin_elementwise_max(a, b)"}, {"RRS", "__builtin_elementwise_max(a, (R)b)"}}});
    for (const char* f : {"fmin", "min"})
      t.push_back({f, {{"RRR", "__builtin_elementwise_min(a, b)"}, {"RRS", "__builtin_elementwise_min(a, (R)b)"}}});
    for (const char* f : {"pow", "powr", "atan2", "fmod", "copysign", "hypot", "fdim", "remainder", "nextafter",
                          "maxmag", "minmag", "native_divide", "native_powr"})
      t.push_back({f, {{"RRR"}}});
    t.push_back({"step", {{"RRR", "b < a ? (R)0 : (R)1"}, {"RSR", "b < a ? (R)0 : (R)1"}}});
    t.push_back({"clamp",
                 {{"RRRR", "__builtin_elementwise_min(__builtin_elementwise_max(a, b), c)"},
                  {"RRSS", "__builtin_elementwise_min(__builtin_elementwise_max(a, (R)b), (R)c)"}}});
    // mix and mad keep OpenCL's own, whose rounding (fused or not) an expression need not match
    t.push_back({"mix", {{"RRRR"}, {"RRRS"}}});
    t.push_back({"smoothstep", {{"RRRR"}, {"RSSR"}}});
    t.push_back({"fma", {{"RRRR"}}});
    t.push_back({"mad", {{"RRRR"}}});
    // OpenCL's select and ?: both take each lane from the mask's sign bit.
    t.push_back({"select", {{"RRRM", "c ? b : a"}, {"MMMM", "c ? b : a"}}});
    for (const char* f : {"isnan", "isinf", "isfinite", "isnormal", "signbit"}) t.push_back({f, {{"MR"}}});
    t.push_back({"any", {{"IM", "__builtin_reduce_or(a) < 0"}}});
    t.push_back({"all", {{"IM", "__builtin_reduce_and(a) < 0"}}});
    return t;
  }();
  return table;
}

// One overload of `name` at lane type R / mask type M.
std::string overload(const char* name, const Form& form, const std::string& r, const std::string& m) {
  auto type = [&](char c) {
    return c == 'R' ? r : c == 'M' ? m : c == 'I' ? std::string("int") : std::string("scalar");
  };
  std::string params, lo, hi;
  for (int i = 1; form.sig[i]; ++i) {
    const char v = char('a' + i - 1);
    params += fmt::format("{}{} {}", i > 1 ? ", " : "", type(form.sig[i]), v);
    const bool lanes = form.sig[i] != 'S';
    lo += fmt::format("{}{}{}", i > 1 ? ", " : "", v, lanes ? ".lo" : "");
    hi += fmt::format("{}{}{}", i > 1 ? ", " : "", v, lanes ? ".hi" : "");
  }
  const std::string out = type(form.sig[0]);
  if (form.body) {
    std::string body = form.body;
    for (size_t at; (at = body.find("(R)")) != std::string::npos;) body.replace(at, 3, "(" + r + ")");
    return fmt::format("OVERLOADED {} {}({}) {{ return {}; }}\n", out, name, params, body);
  }
  return fmt::format("OVERLOADED {0} {1}({2}) {{ {0} r; r.lo = {1}({3}); r.hi = {1}({4}); return r; }}\n", out, name,
                     params, lo, hi);
}

// Every identifier in `text` that is followed by an opening parenthesis.
std::set<std::string, std::less<>> called_names(const std::string& text) {
  std::set<std::string, std::less<>> names;
  auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (size_t i = 0; i < text.size();) {
    if (!word(text[i])) { ++i; continue; }
    size_t j = i;
    while (j < text.size() && word(text[j])) ++j;
    size_t k = j;
    while (k < text.size() && text[k] == ' ') ++k;
    if (k < text.size() && text[k] == '(') names.emplace(text, i, j - i);
    i = j;
  }
  return names;
}

}  // namespace

std::string wide_lane_types(int width, const std::string& scalar, const std::string& mask_scalar,
                            const std::string& body) {
  std::string out =
      "// OpenCL's vectors stop at 16 lanes: a wider packet is a Clang vector whose halves are\n"
      "// OpenCL's. Each builtin the kernel calls gets an overload for it: Clang's vector\n"
      "// operations where they give OpenCL's result, else the builtin on the two halves.\n"
      "#define OVERLOADED __attribute__((overloadable)) inline\n";
  auto names = called_names(body);
  if (names.count("SEL")) names.emplace("select");  // the prelude's macros call these two
  if (names.count("M_ANY")) names.emplace("any");
  std::vector<const Builtin*> used;
  for (const auto& b : builtins())
    if (names.count(b.name)) used.push_back(&b);
  for (int w = 32; w <= width; w *= 2) {
    const std::string r = fmt::format("real{}", w), m = fmt::format("mask{}", w);
    out += fmt::format("typedef {0} {1} __attribute__((ext_vector_type({3})));\n"
                       "typedef {2} {4} __attribute__((ext_vector_type({3})));\n",
                       scalar, r, mask_scalar, w, m);
    // A narrower level serves only the halves of the next: its Clang-operation forms would go unused.
    for (const Builtin* b : used)
      for (const Form& form : b->forms)
        if (w == width || !form.body) out += overload(b->name, form, r, m);
  }
  out += fmt::format("typedef real{0} real;\ntypedef mask{0} mask;\n", width);
  return out;
}

}  // namespace sdfc::codegen::detail
