#include "shard.hpp"

#include <fmt/format.h>

#include <sdfrt/region_file.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <stdexcept>

namespace sdfc::cli {

Shard parse_shard(const std::string& text) {
  static const std::regex re(R"(^(\d{1,6})/(\d{1,6})$)");
  std::smatch m;
  if (!std::regex_match(text, m, re))
    throw std::invalid_argument(fmt::format(
        "--shard '{}': expected TASK/COUNT with TASK counted from 0, e.g. 0/4 "
        "(in a Slurm array: $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT)",
        text));
  Shard s{std::stoi(m[1]), std::stoi(m[2])};
  if (s.count < 1 || s.index >= s.count)
    throw std::invalid_argument(fmt::format("--shard '{}': TASK must be 0 to {} for COUNT {}", text,
                                            std::max(s.count - 1, 0), s.count));
  return s;
}

ShardMode parse_shard_mode(const std::string& text) {
  if (text == "contiguous") return ShardMode::Contiguous;
  if (text == "strided") return ShardMode::Strided;
  const std::string hint = !text.empty() && text[0] == 's' ? " (did you mean 'strided'?)"
                           : !text.empty() && text[0] == 'c' ? " (did you mean 'contiguous'?)" : "";
  throw std::invalid_argument(fmt::format("--shard-mode '{}': expected contiguous or strided{}", text, hint));
}

IndexSlice shard_slice(std::int64_t n, Shard shard, ShardMode mode) {
  const std::int64_t k = shard.index, count = shard.count;
  if (mode == ShardMode::Strided) return {k, n, count};
  return {k * n / count, (k + 1) * n / count, 1};
}

std::vector<int> shard_items(const std::vector<int>& items, Shard shard, ShardMode mode) {
  std::vector<int> out;
  const IndexSlice s = shard_slice(std::int64_t(items.size()), shard, mode);
  for (std::int64_t i = s.begin; i < s.end; i += s.stride) out.push_back(items[std::size_t(i)]);
  return out;
}

Rect parse_region(const std::string& text, int width, int height) {
  static const std::regex re(R"(^\s*(\d{1,5})\s*,\s*(\d{1,5})\s*,\s*(\d{1,5})\s*,\s*(\d{1,5})\s*$)");
  std::smatch m;
  if (!std::regex_match(text, m, re))
    throw std::invalid_argument(
        fmt::format("--region '{}': expected X0,Y0,X1,Y1 in pixels, X1 and Y1 one past the last pixel "
                    "(e.g. 0,0,1920,540: the top half of a 1920x1080 image)",
                    text));
  Rect r{std::stoi(m[1]), std::stoi(m[2]), std::stoi(m[3]), std::stoi(m[4])};
  if (r.x1 <= r.x0 || r.y1 <= r.y0 || r.x1 > width || r.y1 > height)
    throw std::invalid_argument(fmt::format("--region '{}': needs X0 < X1 <= {} and Y0 < Y1 <= {} (the image is {}x{})",
                                            text, width, height, width, height));
  return r;
}

Rect strip_region(int width, int height, int part, int parts) {
  if (parts < 1 || parts > height)
    throw std::invalid_argument(fmt::format("--parts {}: a {}-row image splits into 1 to {} strips", parts, height, height));
  if (part < 0 || part >= parts) throw std::invalid_argument(fmt::format("part {} of {} does not exist", part, parts));
  const long long h = height;
  return Rect{0, int(part * h / parts), width, int((part + 1) * h / parts)};
}

namespace {

std::uintmax_t size_of(const std::string& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  return ec ? 0 : size;
}

bool ends_with_png_iend(const std::string& path, std::uintmax_t size) {
  static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82};
  static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (size < sizeof signature + sizeof iend) return false;
  std::ifstream in(path, std::ios::binary);
  unsigned char head[8], tail[12];
  in.read(reinterpret_cast<char*>(head), sizeof head);
  in.seekg(std::streamoff(size - sizeof tail));
  in.read(reinterpret_cast<char*>(tail), sizeof tail);
  return in && std::memcmp(head, signature, sizeof head) == 0 && std::memcmp(tail, iend, sizeof tail) == 0;
}

bool pfm_has_its_size(const std::string& path, std::uintmax_t size) {
  std::ifstream in(path, std::ios::binary);
  std::string kind;
  long long w = 0, h = 0;
  double scale = 0;
  if (!(in >> kind >> w >> h >> scale) || (kind != "Pf" && kind != "PF") || w < 1 || h < 1) return false;
  in.get();  // the one whitespace after the scale
  const auto header = static_cast<std::uintmax_t>(in.tellg());
  return size == header + std::uintmax_t(w) * std::uintmax_t(h) * (kind == "PF" ? 3u : 1u) * sizeof(float);
}

}  // namespace

bool output_complete(const std::string& path) {
  const std::uintmax_t size = size_of(path);
  if (size == 0) return false;
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".png") return ends_with_png_iend(path, size);
  if (ext == ".pfm") return pfm_has_its_size(path, size);
  if (ext == ".region") {
    try {
      sdfrt::RegionReader reader(path);
      return true;
    } catch (const std::exception&) {
      return false;
    }
  }
  return true;
}

}  // namespace sdfc::cli
