#pragma once
// Adaptive resolution while the camera moves: learns the renderer's cost per
// pixel from recent frames and picks the largest image (smallest pixel
// divisor) expected to render within the frame-time budget.
namespace sdfc::viewer {

class ResolutionGovernor {
 public:
  // 50 ms per frame = the 20 fps.
  explicit ResolutionGovernor(double budget_ms = 50.0) : budget_ms_(budget_ms) {}

  // Divisor of the window size for a frame in motion: 1, 2, 3, 4, 6 or 8.
  int divisor(int width, int height) const;
  // Feeds back the time a frame of `pixels` took.
  void record(long long pixels, double ms);
  bool calibrated() const noexcept { return ns_per_pixel_ > 0; }

 private:
  double budget_ms_;
  double ns_per_pixel_ = 0;  // running estimate; 0 until the first frame
};

}  // namespace sdfc::viewer
