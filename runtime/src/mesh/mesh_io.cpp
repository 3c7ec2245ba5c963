// STL, OBJ and PLY writers. Each goes through AtomicFile, so a failed or
// interrupted write never leaves a half file under the final name; data
// is batched into ~1 MiB writes.
#include <sdfrt/mesh/mesh_io.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "image_io/atomic_file.hpp"

namespace sdfrt::mesh {

namespace {

class Batched {
 public:
  explicit Batched(AtomicFile& f) : file_(f) {}
  ~Batched() = default;
  template <typename T>
  void put(const T& v) { raw(&v, sizeof v); }
  void raw(const void* p, std::size_t n) {
    buf_.append(static_cast<const char*>(p), n);
    if (buf_.size() > (1 << 20)) flush();
  }
  void text(const std::string& s) { raw(s.data(), s.size()); }
  void flush() {
    if (!buf_.empty()) file_.write(buf_.data(), buf_.size());
    buf_.clear();
  }

 private:
  AtomicFile& file_;
  std::string buf_;
};

Vec3f facet_normal(const Mesh& m, const Tri& t) {
  const Vec3f &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
  float u[3], w[3];
  for (int i = 0; i < 3; ++i) u[i] = b[i] - a[i], w[i] = c[i] - a[i];
  Vec3f n{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (len > 0) for (float& x : n) x /= len;
  return n;
}

void write_stl(Batched& out, const Mesh& m) {
  char header[80] = {};
  std::snprintf(header, sizeof header, "binary STL written by sdfc mesh");
  out.raw(header, 80);
  out.put(std::uint32_t(m.triangles.size()));
  for (const Tri& t : m.triangles) {
    out.put(facet_normal(m, t));
    for (int v = 0; v < 3; ++v) out.put(m.vertices[t[v]]);
    out.put(std::uint16_t(0));
  }
}

void write_obj(Batched& out, const Mesh& m) {
  out.text(fmt::format("# written by sdfc mesh: {} vertices, {} triangles\n", m.vertices.size(), m.triangles.size()));
  const bool colour = !m.colours.empty();
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    const Vec3f& v = m.vertices[i];
    if (colour)
      out.text(fmt::format("v {} {} {} {:.4f} {:.4f} {:.4f}\n", v[0], v[1], v[2], m.colours[i][0] / 255.0,
                           m.colours[i][1] / 255.0, m.colours[i][2] / 255.0));
    else
      out.text(fmt::format("v {} {} {}\n", v[0], v[1], v[2]));
  }
  for (const Tri& t : m.triangles) out.text(fmt::format("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1));
}

void write_ply(Batched& out, const Mesh& m) {
  const bool colour = !m.colours.empty();
  out.text(fmt::format("ply\nformat binary_little_endian 1.0\ncomment written by sdfc mesh\nelement vertex {}\n"
                       "property float x\nproperty float y\nproperty float z\n{}element face {}\n"
                       "property list uchar int vertex_indices\nend_header\n",
                       m.vertices.size(),
                       colour ? "property uchar red\nproperty uchar green\nproperty uchar blue\n" : "", m.triangles.size()));
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    out.put(m.vertices[i]);
    if (colour) out.put(m.colours[i]);
  }
  for (const Tri& t : m.triangles) {
    out.put(std::uint8_t(3));
    for (int v = 0; v < 3; ++v) out.put(std::int32_t(t[v]));
  }
}

}  // namespace

std::optional<Format> format_for(const std::string& path) {
  auto dot = path.find_last_of('.');
  if (dot == std::string::npos) return std::nullopt;
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == "stl") return Format::Stl;
  if (ext == "obj") return Format::Obj;
  if (ext == "ply") return Format::Ply;
  return std::nullopt;
}

bool holds_colour(Format f) { return f != Format::Stl; }

void write_mesh(const std::string& path, Format format, const Mesh& mesh) {
  static_assert(sizeof(Vec3f) == 12 && sizeof(Rgb8) == 3, "packed file records");
  AtomicFile file(path);
  Batched out(file);
  switch (format) {
    case Format::Stl: write_stl(out, mesh); break;
    case Format::Obj: write_obj(out, mesh); break;
    case Format::Ply: write_ply(out, mesh); break;
  }
  out.flush();
  file.commit();
}

}  // namespace sdfrt::mesh
