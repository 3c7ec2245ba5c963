#pragma once
// `sdfc view --events FILE`: the viewer driven by a script of real SDL
// events, for tests of the binary and for pictures of the panel. One
// command a line ('#' starts a comment):
//   key NAME        a key press: F2, h, 3, shift+3, ctrl+s (SDL's key names)
//   set PATH VALUE  a panel edit, as dragging the value's slider to VALUE
//   wait SECONDS    keep the viewer running that long
//   settle          run until no build or hi-res render is running and the picture is final
//   snap FILE.png   the window as shown (picture and panel) to a PNG
//   hires W H N     the size and samples of the next hi-res render (key h)
//   quit            close the viewer
#include <string>
#include <vector>

#include "viewer/viewer.hpp"

namespace sdfc::viewer {

struct ScriptCommand {
  int line = 0;
  std::string verb, arg, arg2, arg3;
};

// Reads and checks the whole script first: a SceneError "FILE:LINE:COL: error: ..." for a bad line.
std::vector<ScriptCommand> read_event_script(const std::string& path);

// Runs the commands between viewer steps; after the last one the viewer
// runs on until it is closed (a script without `quit` hands over to the user).
void run_event_script(Viewer& viewer, SdlWindow& window, SceneSession& scene, const std::vector<ScriptCommand>& script);

}  // namespace sdfc::viewer
