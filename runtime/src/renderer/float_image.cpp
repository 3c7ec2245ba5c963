#include <sdfrt/float_image.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <mutex>
#include <stdexcept>

namespace sdfrt {

namespace {
// A frame is tens of MB (1280x720 with its AOV planes: 40 MB). glibc gives
// blocks over 32 MB a fresh mapping and unmaps them when freed, so every
// frame would fault in each of its 4 KiB pages again: on a virtual machine
// that was a third of the viewer's frame time. Dropped planes of 1 MB and
// more are kept for the next image instead, at most two (the frame on show
// and the one being drawn).
constexpr std::size_t kKeepFrom = std::size_t(1) << 18;  // floats
constexpr std::size_t kKept = 2;

struct Recycled {
  std::mutex mutex;
  std::vector<std::vector<float>> blocks;
};
Recycled& recycled() {
  static Recycled* r = new Recycled;  // never destroyed: images may outlive static destruction
  return *r;
}

void recycle(std::vector<float>&& v) noexcept {
  if (v.capacity() < kKeepFrom) return;
  try {
    Recycled& r = recycled();
    std::lock_guard lock(r.mutex);
    if (r.blocks.size() == kKept) r.blocks.erase(r.blocks.begin());  // the oldest goes
    r.blocks.push_back(std::move(v));
  } catch (...) {
    // not kept: the block is simply freed
  }
}

// n zeros, in a kept block that holds them without more than doubling the need.
std::vector<float> zeros(std::size_t n) {
  std::vector<float> v;
  if (n >= kKeepFrom) {
    Recycled& r = recycled();
    std::lock_guard lock(r.mutex);
    auto fits = [n](const std::vector<float>& b) { return b.capacity() >= n && b.capacity() <= 2 * n; };
    auto it = std::find_if(r.blocks.begin(), r.blocks.end(), fits);
    if (it != r.blocks.end()) {
      v = std::move(*it);
      r.blocks.erase(it);
    }
  }
  v.assign(n, 0.0f);
  return v;
}
}  // namespace

FloatImage::FloatImage(int w, int h, std::vector<std::string> names)
    : width(w), height(h), plane_names(std::move(names)) {
  if (w < 1 || h < 1) {
    throw std::invalid_argument(fmt::format("image size must be positive, got {}x{}", w, h));
  }
  data = zeros(plane_size() * plane_names.size());
}

FloatImage& FloatImage::operator=(FloatImage&& other) noexcept {
  if (this == &other) return *this;
  recycle(std::move(data));
  width = other.width;
  height = other.height;
  plane_names = std::move(other.plane_names);
  data = std::move(other.data);
  return *this;
}

FloatImage::~FloatImage() { recycle(std::move(data)); }

float FloatImage::at(int k, int x, int y) const {
  if (k < 0 || k >= planes() || x < 0 || x >= width || y < 0 || y >= height) {
    throw std::out_of_range(fmt::format("FloatImage::at({}, {}, {}) outside {}x{} with {} planes",
                                        k, x, y, width, height, planes()));
  }
  return data[static_cast<std::size_t>(k) * plane_size() +
              static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
              static_cast<std::size_t>(x)];
}

int FloatImage::plane_index(std::string_view name) const {
  for (std::size_t i = 0; i < plane_names.size(); ++i) {
    if (plane_names[i] == name) return static_cast<int>(i);
  }
  return -1;
}

std::span<const float> FloatImage::plane(int k) const {
  return std::span<const float>(data).subspan(static_cast<std::size_t>(k) * plane_size(),
                                              plane_size());
}

std::span<float> FloatImage::plane(int k) {
  return std::span<float>(data).subspan(static_cast<std::size_t>(k) * plane_size(), plane_size());
}

}  // namespace sdfrt
