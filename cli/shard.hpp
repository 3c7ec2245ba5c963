#pragma once
// How a render farm task finds its share: frames or still parts split over
// N tasks (--shard k/N), full-width strips of a still (--parts), explicit
// regions (--region), and whether a frame's files are already complete (so
// a re-queued task resumes instead of starting over).
#include <cstdint>
#include <string>
#include <vector>

namespace sdfc::cli {

struct Shard {
  int index = 0, count = 1;  // task `index` (0-based) of `count`
};
enum class ShardMode { Contiguous, Strided };

struct Rect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // pixels [x0, x1) x [y0, y1)
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
};

// "k/N" with 0 <= k < N; throws std::invalid_argument with what was expected.
Shard parse_shard(const std::string& text);
// "contiguous" or "strided" (did you mean for a near miss).
ShardMode parse_shard_mode(const std::string& text);

// Indices begin, begin + stride, ... below end: a task's share of n items,
// computed without listing them (a --frames range may hold 2^31 frames).
struct IndexSlice {
  std::int64_t begin = 0, end = 0, stride = 1;
  std::int64_t size() const { return end > begin ? (end - begin + stride - 1) / stride : 0; }
};

// The share of task k of items 0 .. n-1: contiguous gives a run of
// neighbouring items (sizes differ by at most one), strided every N-th item
// from the k-th.
IndexSlice shard_slice(std::int64_t n, Shard shard, ShardMode mode);
// The same share of a list of items.
std::vector<int> shard_items(const std::vector<int>& items, Shard shard, ShardMode mode);

// "x0,y0,x1,y1" inside a width x height image, x1 > x0 and y1 > y0.
Rect parse_region(const std::string& text, int width, int height);
// Part `part` of `parts` full-width strips of a width x height image (strip
// heights differ by at most one row); throws if there are more parts than rows.
Rect strip_region(int width, int height, int part, int parts);

// True when the file exists and ends as a finished file of its kind does
// (PNG: the IEND chunk; PFM: the size its header gives; region files: the
// size their header gives). Other kinds: when it exists and is not empty.
bool output_complete(const std::string& path);

}  // namespace sdfc::cli
