#pragma once
// Tile progress on stderr: a redrawn bar on a TTY, sparse lines otherwise.
#include <chrono>
#include <cstdio>
#include <functional>
#include <string>

namespace sdfrt {

class ProgressBar {
 public:
  enum class Style {
    Auto,         // Interactive when the stream is a TTY, else Lines
    Interactive,  // "\r[#####.....] 12/48 tiles  1.2s elapsed  ETA 3.4s"
    Lines,        // one such line (no bar) per ~10% at most
  };

  explicit ProgressBar(std::string unit = "tiles", Style style = Style::Auto,
                       std::FILE* out = stderr);
  ~ProgressBar();  // finish()
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void update(int done, int total);
  // Ends an interactive bar with a newline; idempotent.
  void finish();
  // For RenderOptions::progress; the bar must outlive the render.
  std::function<void(int, int)> callback() {
    return [this](int done, int total) { update(done, total); };
  }

 private:
  std::string format_status(int done, int total, double elapsed_s) const;

  std::string unit_;
  bool interactive_;
  std::FILE* out_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_{};
  int last_decile_ = 0;  // lines mode: tenths already reported
  bool drew_ = false;
  bool finished_ = false;
};

}  // namespace sdfrt
