// Output names: frame sequences (--frames, %04d, --number-from) and the
// files beside an image (AOVs, the partial image of a stopped render).
#include <fmt/format.h>

#include <filesystem>
#include <regex>
#include <stdexcept>

#include "offline_render.hpp"

namespace sdfc::cli {

std::string aov_path(const std::string& beauty, const std::string& aov) {
  std::filesystem::path p(beauty);
  return (p.parent_path() / (p.stem().string() + "." + aov + ".pfm")).string();
}

std::string partial_path(const std::string& beauty) {
  std::filesystem::path p(beauty);
  return (p.parent_path() / (p.stem().string() + ".partial" + p.extension().string())).string();
}

std::vector<int> parse_frames(const std::string& spec) {
  static const std::regex re(R"(^(\d+)(?::(\d+)(?::(\d+))?)?$)");
  std::smatch m;
  if (!std::regex_match(spec, m, re))
    throw std::invalid_argument(fmt::format("--frames '{}': expected N, FIRST:LAST or FIRST:LAST:STEP (e.g. 0:120)", spec));
  auto number = [&](const std::string& digits) {
    if (digits.size() > 9) throw std::invalid_argument(fmt::format("--frames '{}': frame numbers go up to 999999999", spec));
    return std::stoi(digits);
  };
  int first = number(m[1]);
  int last = m[2].matched ? number(m[2]) : first;
  int step = m[3].matched ? number(m[3]) : 1;
  if (last < first || step < 1)
    throw std::invalid_argument(fmt::format("--frames '{}': LAST must not be before FIRST and STEP must be at least 1", spec));
  if ((last - first) / step >= 100000) throw std::invalid_argument(fmt::format("--frames '{}': more than 100000 frames", spec));
  std::vector<int> out;
  for (int i = first; i <= last; i += step) out.push_back(i);
  return out;
}

namespace {
const std::regex kFrameField(R"(%(0?\d*)d)");
}

bool has_frame_field(const std::string& pattern) {
  return std::distance(std::sregex_iterator(pattern.begin(), pattern.end(), kFrameField), std::sregex_iterator()) == 1;
}

std::string frame_path(const std::string& pattern, int frame) {
  std::smatch m;
  if (!has_frame_field(pattern) || !std::regex_search(pattern, m, kFrameField))
    throw std::invalid_argument(fmt::format(
        "-o '{}': a sequence needs one frame-number field such as %04d in the file name", pattern));
  std::string flags = m[1];
  if (flags.size() > 2)  // %0Nd up to 99 digits wide; a wider field is a typo, not a name
    throw std::invalid_argument(fmt::format("-o '{}': the frame field is wider than 99 digits", pattern.substr(0, 200)));
  int width = flags.empty() ? 0 : std::stoi(flags);
  std::string num = fmt::format("{}", frame);
  if (static_cast<int>(num.size()) < width) num = std::string(width - num.size(), flags[0] == '0' ? '0' : ' ') + num;
  return m.prefix().str() + num + m.suffix().str();
}

int sequence_number(const std::vector<int>& frames, std::size_t index, const std::string& number_from) {
  if (number_from == "0") return static_cast<int>(index);
  if (number_from == "first") return frames.front() + static_cast<int>(index);
  throw std::invalid_argument(fmt::format("--number-from '{}': expected 0 or first", number_from));
}

}  // namespace sdfc::cli
