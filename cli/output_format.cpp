#include "output_format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sdfrt/video_writer.hpp>
#include <stdexcept>

namespace sdfc::cli {
namespace {

struct Entry {
  Format format;
  const char* name;
  std::vector<const char*> extensions;
};

const std::vector<Entry>& table() {
  static const std::vector<Entry> t = {
      {Format::Png, "png", {".png"}},  {Format::Exr, "exr", {".exr"}},          {Format::Pfm, "pfm", {".pfm"}},
      {Format::Jpeg, "jpg", {".jpg", ".jpeg"}}, {Format::Mp4, "mp4", {".mp4"}}, {Format::Mkv, "mkv", {".mkv"}},
      {Format::Webm, "webm", {".webm"}},
  };
  return t;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

}  // namespace

const std::vector<std::string>& format_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const auto& e : table()) v.push_back(e.name);
    return v;
  }();
  return names;
}

const char* format_name(Format f) {
  for (const auto& e : table())
    if (e.format == f) return e.name;
  return "?";
}

bool is_video(Format f) { return f == Format::Mp4 || f == Format::Mkv || f == Format::Webm; }

Format output_format(const std::string& path, const std::string& forced) {
  for (const auto& e : table())
    if (!forced.empty() && forced == e.name) return e.format;
  if (!forced.empty())
    throw std::invalid_argument(fmt::format("--format '{}': expected one of {}", forced, fmt::join(format_names(), ", ")));
  const std::string ext = lower(std::filesystem::path(path).extension().string());
  for (const auto& e : table())
    for (const char* x : e.extensions)
      if (ext == x) return e.format;
  throw std::invalid_argument(fmt::format(
      "-o '{}': {}; sdfc writes .png, .exr, .pfm, .jpg (.jpeg), .mp4, .mkv and .webm "
      "(or name one with --format)",
      path, ext.empty() ? "the name has no extension" : fmt::format("unknown file type '{}'", ext)));
}

OutputChoices resolve_choices(Format f, OutputChoices c, bool aovs) {
  const std::string kind = fmt::format(".{}", format_name(f));
  auto refuse = [&](const std::string& what) { throw std::invalid_argument(fmt::format("{} {}", kind, what)); };
  if (c.alpha && f != Format::Png && f != Format::Exr)
    refuse("has no alpha channel; --alpha (render.alpha) needs .png or .exr");
  if (aovs && is_video(f)) refuse("holds no AOVs; write them with an .exr sequence (or PNG + PFM files) instead");
  switch (f) {
    case Format::Png:
      if (c.bit_depth == 0) c.bit_depth = 8;
      if (c.bit_depth != 8 && c.bit_depth != 16) refuse(fmt::format("takes --bit-depth 8 or 16, not {}", c.bit_depth));
      break;
    case Format::Exr:
      if (c.bit_depth == 0) c.bit_depth = 16;
      if (c.bit_depth != 16 && c.bit_depth != 32)
        refuse(fmt::format("takes --bit-depth 16 (half, the default) or 32 (float), not {}", c.bit_depth));
      break;
    case Format::Pfm:
      if (c.bit_depth == 0) c.bit_depth = 32;
      if (c.bit_depth != 32) refuse(fmt::format("is always 32-bit float, not --bit-depth {}", c.bit_depth));
      break;
    default:  // JPEG and video: 8 bits
      if (c.bit_depth == 0) c.bit_depth = 8;
      if (c.bit_depth != 8) refuse(fmt::format("is 8 bits per channel, not --bit-depth {}", c.bit_depth));
  }
  if (f == Format::Jpeg) {
    if (c.quality < 0) c.quality = 90;
    if (c.quality < 1 || c.quality > 100) refuse(fmt::format("takes --quality 1-100, not {}", c.quality));
  } else if (is_video(f)) {
    const auto container = f == Format::Webm ? sdfrt::VideoContainer::WebM : sdfrt::VideoContainer::Mp4;
    const int max_crf = f == Format::Webm ? 63 : 51;
    if (c.quality < 0) c.quality = sdfrt::VideoWriter::default_crf(container);
    if (c.quality > max_crf) refuse(fmt::format("takes --quality as a CRF from 0 (best) to {}, not {}", max_crf, c.quality));
  } else if (c.quality >= 0) {
    refuse("has no quality setting (--quality is for .jpg and video)");
  }
  return c;
}

}  // namespace sdfc::cli
