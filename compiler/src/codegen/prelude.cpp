// The types the width-generic stdlib is written against, for one SIMD width
// and precision. At width 1 `real` is a scalar (a GPU work-item is one
// pixel); at width N a work-item shades N pixels as one packet and `mask`
// holds a lane mask, which every loop uses to freeze finished lanes.
#include "prelude.hpp"

#include "wide_lanes.hpp"

#include <fmt/format.h>

namespace sdfc::codegen::detail {

std::string prelude(int width, int rows, ir::Precision precision, bool animated, int unlocked, const std::string& body) {
  bool dbl = precision == ir::Precision::Double;
  std::string scalar = dbl ? "double" : "float";
  std::string m = dbl ? "long" : "int";  // vector comparisons give lanes as wide as the operands
  std::string out;
  if (dbl) out += "#pragma OPENCL EXTENSION cl_khr_fp64 : enable\n";
  const int cols = width / rows;
  out += fmt::format("#define SDFC_WIDTH {}\n", width);
  out += fmt::format("#define SDFC_PACKET_W {}  /* a packet is SDFC_PACKET_W x SDFC_PACKET_H pixels */\n", cols);
  out += fmt::format("#define SDFC_PACKET_H {}\n", rows);
  out += fmt::format("typedef {} scalar;\n", scalar);
  if (width == 1) {
    // Scalar comparisons give int whatever the operand type, and scalar
    // select() wants a mask as wide as the operands, so width 1 uses ?: instead.
    out += fmt::format("typedef {} real;\ntypedef int mask;\n", scalar);
    out += "#define M_ANY(m) ((m) != 0)\n";
    out += "#define SEL(a, b, m) ((m) ? (b) : (a))\n";
    out += fmt::format("#define LANE_IDS (({})0)\n", scalar);
    out += fmt::format("#define LANE_X (({})0)\n#define LANE_Y (({})0)\n", scalar, scalar);
    out += dbl ? "#define LOAD_REAL(ptr) ((double)*(ptr))\n#define STORE_REAL(v, ptr) (*(ptr) = (float)(v))\n"
               : "#define LOAD_REAL(ptr) (*(ptr))\n#define STORE_REAL(v, ptr) (*(ptr) = (v))\n";
    out += "#define STORE_PACKET(v, ptr, stride) STORE_REAL(v, ptr)\n";
  } else {
    if (width > 16) out += wide_lane_types(width, scalar, m, body);
    else out += fmt::format("typedef {0}{1} real;\ntypedef {2}{1} mask;\n", scalar, width, m);
    out += "#define M_ANY(m) any(m)\n";
    out += "#define SEL(a, b, m) select((a), (b), (m))  /* per lane: m ? b : a */\n";
    std::string lanes;
    for (int i = 0; i < width; ++i) lanes += fmt::format("{}{}", i ? ", " : "", i);
    out += fmt::format("#define LANE_IDS ((real)({}))\n", lanes);
    // Lane i is pixel (i % cols, i / cols) of the packet.
    std::string lx, ly;
    for (int i = 0; i < width; ++i) {
      lx += fmt::format("{}{}", i ? ", " : "", i % cols);
      ly += fmt::format("{}{}", i ? ", " : "", i / cols);
    }
    out += fmt::format("#define LANE_X ((real)({}))\n#define LANE_Y ((real)({}))\n", lx, ly);
    if (width > 16)  // lane by lane: only the probe and mesh kernels load and store whole packets
      out += fmt::format("#define LOAD_REAL(ptr) load_lanes(ptr)\n#define STORE_REAL(v, ptr) store_lanes((v), (ptr))\n"
                         "inline real load_lanes(__global const float* p) {{ real r; for (int i = 0; i < {0}; ++i) r[i] = p[i]; return r; }}\n"
                         "inline void store_lanes(real v, __global float* p) {{ for (int i = 0; i < {0}; ++i) p[i] = (float)v[i]; }}\n",
                         width);
    else if (dbl)
      out += fmt::format("#define LOAD_REAL(ptr) convert_double{0}(vload{0}(0, (ptr)))\n"
                         "#define STORE_REAL(v, ptr) vstore{0}(convert_float{0}(v), 0, (ptr))\n", width);
    else
      out += fmt::format("#define LOAD_REAL(ptr) vload{0}(0, (ptr))\n#define STORE_REAL(v, ptr) vstore{0}((v), 0, (ptr))\n", width);
    if (rows == 1) {
      out += "#define STORE_PACKET(v, ptr, stride) STORE_REAL(v, ptr)\n";
    } else {
      // One store per pixel row of the packet, `stride` floats apart.
      out += "#define STORE_PACKET(v, ptr, stride) do { \\\n";
      for (int r = 0; r < rows; ++r) {
        std::string sw;
        for (int c = 0; c < cols; ++c) sw += fmt::format("{:x}", r * cols + c);
        std::string part = fmt::format("(v).s{}", sw);
        if (width > 16) {  // swizzles name 16 lanes at most
          part = "__builtin_shufflevector((v), (v)";
          for (int c = 0; c < cols; ++c) part += fmt::format(", {}", r * cols + c);
          part += ")";
        }
        if (cols == 1)
          out += fmt::format("    (ptr)[{} * (stride)] = (float)({}); \\\n", r, part);
        else
          out += fmt::format("    vstore{}({}, 0, (ptr) + {} * (stride)); \\\n", cols,
                             dbl ? fmt::format("convert_float{}({})", cols, part) : part, r);
      }
      out += "} while (0)\n";
    }
  }
  out += "#define M_TRUE ((mask)(-1))\n";
  out += "#define K(x) ((scalar)(x))  /* a literal in the kernel's precision, for builtin arguments */\n";
  out += "typedef struct { real x, y, z; } vec3;\n";
  if (unlocked > 0)
    out += fmt::format("// {} unlocked value(s) come after the frame block: the time and them are the first arguments of every "
                       "function that evaluates the scene\n"
                       "#define TIME_PARAM const scalar time, __global const float* unlocked,\n#define TIME_ARG time, unlocked,\n",
                       unlocked);
  else if (animated)
    out += "// the scene is animated: the frame time is the first argument of every function that evaluates it\n"
           "#define TIME_PARAM const scalar time,\n#define TIME_ARG time,\n";
  else
    out += "// the scene is static: no time argument\n#define TIME_PARAM\n#define TIME_ARG\n";
  return out;
}

}  // namespace sdfc::codegen::detail
