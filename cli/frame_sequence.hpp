#pragma once
// Frame sequences: the frame numbers of --frames (a range, never a list:
// `--frames 0:2147483647` holds three numbers), the names of their files
// (%04d, %%, --number-from).
#include <cstdint>
#include <string>

namespace sdfc::cli {

// FIRST, FIRST + STEP, ... up to LAST (inclusive).
struct FrameRange {
  int first = 0, last = 0, step = 1;
  std::int64_t size() const { return (std::int64_t(last) - first) / step + 1; }
  int at(std::int64_t index) const { return int(first + index * step); }
  int back() const { return at(size() - 1); }
};

// Frame numbers from --frames: "N", "A:B" (inclusive) or "A:B:STEP", each
// number from 0 to 2147483647. Throws std::invalid_argument with what was
// expected.
FrameRange parse_frames(const std::string& spec);

// Expands the one printf-style integer field ("%d", "%04d") of a sequence
// pattern, and "%%" to "%"; throws std::invalid_argument if there is no
// field or more than one. The number is the output frame's: see
// sequence_number.
std::string frame_path(const std::string& pattern, int frame);
bool has_frame_field(const std::string& pattern);

// --number-from: "0" numbers the output frames 0, 1, 2, ...; "first" (the
// default) FIRST, FIRST+1, ... whatever the STEP, so %04d patterns have no
// gaps. `index` is the frame's place in the range. Throws
// std::invalid_argument for anything else.
int sequence_number(const FrameRange& frames, std::int64_t index, const std::string& number_from);

// Refuses, with std::invalid_argument, frames past the time over which
// animated values are checked, a bad --number-from, a video name with a
// frame field and a sequence name without one.
void check_sequence_output(const FrameRange& frames, bool sequence, double fps, const std::string& number_from,
                           const std::string& output, bool video);

}  // namespace sdfc::cli
