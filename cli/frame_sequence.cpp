// Output names: frame sequences (--frames, %04d, %%, --number-from) and the
// files beside an image (AOVs, the partial image of a stopped render).
#include "frame_sequence.hpp"

#include <fmt/format.h>

#include <cctype>
#include <climits>
#include <filesystem>
#include <regex>
#include <stdexcept>

#include "offline_render.hpp"
#include "sdfc/expr/expr.hpp"

namespace sdfc::cli {

std::string aov_path(const std::string& beauty, const std::string& aov) {
  std::filesystem::path p(beauty);
  return (p.parent_path() / (p.stem().string() + "." + aov + ".pfm")).string();
}

std::string partial_path(const std::string& beauty) {
  std::filesystem::path p(beauty);
  return (p.parent_path() / (p.stem().string() + ".partial" + p.extension().string())).string();
}

FrameRange parse_frames(const std::string& spec) {
  static const std::regex re(R"(^(\d+)(?::(\d+)(?::(\d+))?)?$)");
  std::smatch m;
  if (spec.size() > 100 || !std::regex_match(spec, m, re))
    throw std::invalid_argument(fmt::format("--frames '{}': expected N, FIRST:LAST or FIRST:LAST:STEP (e.g. 0:120)",
                                            spec.substr(0, 100)));
  auto number = [&](const std::string& digits) {
    const std::size_t lead = std::min(digits.find_first_not_of('0'), digits.size());
    if (digits.size() - lead > 10 || std::stoll(digits.substr(lead).empty() ? "0" : digits.substr(lead)) > INT_MAX)
      throw std::invalid_argument(fmt::format("--frames '{}': frame numbers go up to {}", spec, INT_MAX));
    return int(std::stoll(digits));
  };
  FrameRange r;
  r.first = number(m[1]);
  r.last = m[2].matched ? number(m[2]) : r.first;
  r.step = m[3].matched ? number(m[3]) : 1;
  if (r.last < r.first || r.step < 1)
    throw std::invalid_argument(fmt::format("--frames '{}': LAST must not be before FIRST and STEP must be at least 1", spec));
  return r;
}

namespace {

// A name pattern split at its frame fields: "%%" is a literal '%', "%d" and
// "%0Nd" / "%Nd" are fields, any other '%' is itself.
struct Pattern {
  std::string prefix, suffix;  // around the first field, with %% collapsed
  int fields = 0;
  std::string flags;  // of the first field: "", "04", "4", ...
  bool too_wide = false;
};

Pattern split(const std::string& s) {
  Pattern p;
  std::string* text = &p.prefix;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '%') {
      *text += s[i];
      continue;
    }
    if (i + 1 < s.size() && s[i + 1] == '%') {
      *text += '%';
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
    if (j >= s.size() || s[j] != 'd') {
      *text += '%';
      continue;
    }
    if (++p.fields == 1) {
      p.flags = s.substr(i + 1, j - i - 1);
      // %0Nd up to 99 digits wide; a wider field is a typo, not a name
      p.too_wide = p.flags.size() > 2 && !(p.flags.size() == 3 && p.flags[0] == '0');
      text = &p.suffix;
    } else {
      *text += s.substr(i, j - i + 1);
    }
    i = j;
  }
  return p;
}

}  // namespace

bool has_frame_field(const std::string& pattern) { return split(pattern).fields == 1; }

std::string frame_path(const std::string& pattern, int frame) {
  const Pattern p = split(pattern);
  if (p.fields != 1)
    throw std::invalid_argument(fmt::format(
        "-o '{}': a sequence needs one frame-number field such as %04d in the file name (write %% for a '%')",
        pattern.substr(0, 200)));
  if (p.too_wide)
    throw std::invalid_argument(fmt::format("-o '{}': the frame field is wider than 99 digits", pattern.substr(0, 200)));
  const int width = p.flags.empty() ? 0 : std::stoi(p.flags);
  std::string num = fmt::format("{}", frame);
  if (static_cast<int>(num.size()) < width) num = std::string(width - num.size(), p.flags[0] == '0' ? '0' : ' ') + num;
  return p.prefix + num + p.suffix;
}

int sequence_number(const FrameRange& frames, std::int64_t index, const std::string& number_from) {
  if (number_from == "0") return static_cast<int>(index);
  if (number_from == "first") return static_cast<int>(frames.first + index);
  throw std::invalid_argument(fmt::format("--number-from '{}': expected 0 or first", number_from));
}

void check_sequence_output(const FrameRange& frames, bool sequence, double fps, const std::string& number_from,
                           const std::string& output, bool video) {
  if (frames.back() / fps > expr::kMaxTime)  // animated values are checked for t in [0, kMaxTime] only
    throw std::invalid_argument(fmt::format("--frames: frame {} is at t = {:.3g} s at {} fps, past the {:g} s over which "
                                            "animated values are checked",
                                            frames.back(), frames.back() / fps, fps, expr::kMaxTime));
  if (video && has_frame_field(output))
    throw std::invalid_argument(fmt::format("-o '{}': a video is one file; drop the frame-number field", output));
  sequence_number(frames, 0, number_from);  // checks --number-from
  if (!video && sequence && frames.size() > 1 && !has_frame_field(output))
    throw std::invalid_argument(fmt::format(
        "-o '{}': {} frames need one frame-number field in the name, e.g. out/frame_%04d.png "
        "(write %% for a '%')", output, frames.size()));
}

}  // namespace sdfc::cli
