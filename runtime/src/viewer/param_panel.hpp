#pragma once
// The F2 parameter panel (Dear ImGui over the SDL renderer): the scene file
// as a tree of its YAML keys with their lines, numbers as sliders (the range
// an unlocked value was built for) or drag fields, colours as colour pickers;
// changed values in yellow. Changes go to LiveValues; after a few idle
// seconds the panel bakes the values into a fresh kernel.
#include <string>

#include "viewer/live_values.hpp"

struct SDL_Window;
struct SDL_Renderer;
union SDL_Event;

namespace sdfc::viewer {

class ParamPanel {
 public:
  ParamPanel(SDL_Window* window, SDL_Renderer* renderer, LiveValues& live, SceneSession& scene);
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
  void tree(const SourceValue& v, const std::string& path);
  void number(const std::string& label, const std::string& path, const SourceValue& v);
  void colour(const std::string& label, const std::string& path);
  void touched(LiveValues::Change c);

  LiveValues& live_;
  SceneSession& scene_;
  bool changed_ = false;
  bool confirm_overwrite_ = false;
  std::string status_;
};

// Seconds of no change before the unlocked kernel is re-specialised.
inline constexpr double kIdleBakeSeconds = 3;

}  // namespace sdfc::viewer
