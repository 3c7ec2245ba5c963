#pragma once
// The F2 parameter panel (Dear ImGui over the SDL renderer): the scene file
// in sections (the scene tree; camera with the current view, bookmarks and
// the hi-res render; lights; materials; effects with render and background;
// anything else), each a tree of its YAML keys with their lines. Numbers
// are sliders (the range an unlocked value was built for) or drag fields,
// three numbers one row, colours colour pickers, true/false checkboxes;
// changed values in yellow. Changes go to LiveValues; after a few idle seconds the panel
// bakes the values into a fresh kernel.
#include <string>

#include "viewer/live_values.hpp"
#include "viewer/view_tools.hpp"

struct SDL_Window;
struct SDL_Renderer;
union SDL_Event;

namespace sdfc::viewer {

class ParamPanel {
 public:
  ParamPanel(SDL_Window* window, SDL_Renderer* renderer, LiveValues& live, SceneSession& scene, ViewTools& tools);
  ~ParamPanel();
  ParamPanel(const ParamPanel&) = delete;
  ParamPanel& operator=(const ParamPanel&) = delete;

  // Feeds an event to the panel; true when the panel used it (the camera should not).
  bool handle(const SDL_Event& e);
  // Draws the panel into the renderer (call between the picture and the present).
  void draw();
  // True once after a change the picture shows (a new frame is due).
  bool take_change();
  // Bakes once the values have been still for a while (call once per step).
  void idle_bake();
  // Ctrl+S / the Save button: a file changed on disk needs a second press.
  void save();
  const std::string& status() const { return status_; }

 private:
  void sections();
  void entry(const std::string& label, const std::string& path, const SourceValue& v);
  void tree(const SourceValue& v, const std::string& path);
  void checkbox(const std::string& label, const std::string& path);
  void number(const std::string& label, const std::string& path, const SourceValue& v);
  void triple(const std::string& label, const std::string& path, bool colour);
  void touched(LiveValues::Change c);

  LiveValues& live_;
  SceneSession& scene_;
  ViewTools& tools_;
  bool changed_ = false;
  bool confirm_overwrite_ = false;
  std::string status_;
};

// The camera section's own part: the view now, the bookmarks (a button
// recalls one) and the hi-res render's size, samples and progress.
// True when the view moved.
bool draw_view_tools(ViewTools& tools);

// Seconds of no change before the unlocked kernel is re-specialised.
inline constexpr double kIdleBakeSeconds = 3;

}  // namespace sdfc::viewer
