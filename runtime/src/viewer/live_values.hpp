#pragma once
// The panel's model: the scene values the user has changed, how each change
// reaches the picture, and saving them into the scene file.
//  - a value the current kernel reads per frame (unlocked) and inside the
//    range it was built for: a new frame, no build;
//  - a value that may be unlocked: one background build with it unlocked
//    (the old kernel keeps drawing), then frames;
//  - a value that shapes the code (a count, a choice, a fractal constant):
//    a background build with it baked, on each change.
// bake() rebuilds with every value baked as a literal, the fastest kernel.
#include <chrono>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "viewer/scene_session.hpp"

namespace sdfc::viewer {

class LiveValues {
 public:
  // Reads the scene file's text as it is now (what save() edits).
  explicit LiveValues(SceneSession& scene);

  enum class Change { Frame, Unlocking, Rebuilding };
  // Sets the number at `path` ("lights[0].point.intensity" or "lights.0.point.intensity").
  Change set(const std::string& path, double value);
  // A true/false value (a checkbox): kept as 1 / 0, written as the word. It shapes the code, so it rebuilds.
  Change set_bool(const std::string& path, bool value);
  double value(const std::string& path) const;  // the edited value, or the file's (true: 1, false: 0)
  bool changed(const std::string& path) const;  // differs from the file
  bool changed_under(const std::string& path) const;  // a value below `path` (a node) differs from the file
  // Background build with every edited value baked; the unlocked slots go.
  void bake();
  bool unlocked_now() const { return !scene_.slots().empty(); }
  // Swaps in a finished background build and gives its slots the values
  // edited while it built. Call once per frame.
  ReloadResult poll();

  // Ctrl+Z / Ctrl+Y: the previous / next value of the last edits.
  bool undo();
  bool redo();
  // When a value last changed (set, undo, redo) or a kernel arrived: the panel bakes after a quiet while.
  std::chrono::steady_clock::time_point last_change() const { return last_change_; }

  enum class Saved { Written, ChangedOnDisk, NothingToSave };
  // Writes the changed values into the file, only their characters. A file
  // changed on disk since it was read is kept unless `overwrite`.
  Saved save(bool overwrite = false);

  // Writes a whole top-level section (the bookmarks) into the file at once,
  // on the same terms as save(); the edited values stay edits.
  Saved save_section(const std::string& key, const std::string& block);

  // The --set overrides of the edits (for a build; also what the panel shows).
  std::vector<std::string> overrides() const;
  // The file as last read or saved, parsed (the panel's tree).
  const SourceValue& file() const { return root_; }
  // Whether a run-time reader takes the value (asked of the front end once per path).
  bool unlockable(const std::string& path) const;

 private:
  struct Step {
    std::string path;
    double before, after;
  };
  Change apply(const std::string& path, double value);
  SceneOptions options_with(const std::vector<std::string>& unlock) const;
  double file_value(const std::string& path) const;
  std::string text_of(const std::string& path, double v) const;  // as the file and --set write it
  void adopt_text(std::string text);

  SceneSession& scene_;
  std::vector<std::string> base_sets_;  // the command line's --set
  std::string text_;                    // the file as read (or last saved)
  SourceValue root_;                    // text_ parsed
  std::map<std::string, double> edits_;
  std::set<std::string> bools_;  // edited paths that hold true/false
  // Asked once per path: whether it unlocks, and the range it needs when the
  // default one is refused by the value's own checks (a Mandelbox scale).
  std::map<std::string, std::optional<std::optional<std::pair<double, double>>>> can_unlock_;
  std::vector<std::string> unlocked_;       // paths the kernel reads per frame, in slot order
  std::vector<Step> done_, undone_;
  std::chrono::steady_clock::time_point last_change_ = std::chrono::steady_clock::now();
};

// "a[1].b" -> "a.1.b": the form --set takes.
std::string dotted_path(const std::string& path);

}  // namespace sdfc::viewer
