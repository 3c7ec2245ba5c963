#include "viewer/event_script.hpp"

#include <SDL.h>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sdfrt/image_io.hpp>
#include <sstream>
#include <thread>

#include "sdfc/support/diagnostics.hpp"

namespace sdfc::viewer {

namespace {
using Clock = std::chrono::steady_clock;

// "shift+3" -> the key and its modifiers; SDLK_UNKNOWN for a name SDL does not know.
std::pair<SDL_Keycode, Uint16> key_of(std::string name) {
  Uint16 mod = KMOD_NONE;
  for (auto [prefix, m] : {std::pair{"shift+", KMOD_LSHIFT}, {"ctrl+", KMOD_LCTRL}, {"alt+", KMOD_LALT}})
    while (name.rfind(prefix, 0) == 0) name.erase(0, std::string(prefix).size()), mod |= m;
  return {SDL_GetKeyFromName(name.c_str()), mod};
}

void step_for(Viewer& v, double seconds) {
  const auto end = Clock::now() + std::chrono::duration<double>(seconds);
  while (Clock::now() < end && v.step()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
}

// Until nothing is building or rendering for a file and a still frame has
// been drawn (at most two minutes).
void settle(Viewer& v, SceneSession& scene) {
  const auto end = Clock::now() + std::chrono::minutes(2);
  int quiet = 0;
  while (Clock::now() < end && quiet < 3 && v.step()) {
    const bool busy = scene.building() || v.tools().hires().running() || v.last_frame().rendered;
    quiet = busy ? 0 : quiet + 1;
  }
}

void snap(SdlWindow& w, const std::string& path) {
  const std::vector<std::uint8_t> rgb = w.capture();
  sdfrt::FloatImage img(w.width(), w.height(), {"r", "g", "b"});
  for (int c = 0; c < 3; ++c)
    for (std::size_t i = 0; i < img.plane_size(); ++i) img.plane(c)[i] = float(rgb[i * 3 + c]) / 255.0f;
  std::cerr << "snap: " << sdfrt::write_png(path, img).path << "\n";
}
}  // namespace

std::vector<ScriptCommand> read_event_script(const std::string& path) {
  std::ifstream in(path);
  if (!in) fail(SourceLoc(std::make_shared<const std::string>(path), 0, 0), "cannot read the events file");
  auto name = std::make_shared<const std::string>(path);
  std::vector<ScriptCommand> out;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    text = text.substr(0, text.find('#'));
    std::istringstream words(text);
    ScriptCommand c;
    c.line = line;
    if (!(words >> c.verb)) continue;
    words >> c.arg >> c.arg2 >> c.arg3;
    const SourceLoc at(name, line, int(text.find(c.verb)) + 1);
    static const std::vector<std::string_view> kVerbs = {"key", "set", "wait", "settle", "snap", "hires", "quit"};
    if (std::find(kVerbs.begin(), kVerbs.end(), c.verb) == kVerbs.end())
      fail(at, fmt::format("unknown command '{}': expected key, set, wait, settle, snap, hires or quit", c.verb),
           did_you_mean(c.verb, kVerbs));
    char* end = nullptr;
    if (c.verb == "key" && key_of(c.arg).first == SDLK_UNKNOWN)
      fail(at, fmt::format("key: expected a key name such as F2, h, 3 or shift+3, got '{}'", c.arg));
    if (c.verb == "wait" && (std::strtod(c.arg.c_str(), &end) < 0 || c.arg.empty() || *end || std::strtod(c.arg.c_str(), nullptr) > 3600))
      fail(at, fmt::format("wait: expected seconds from 0 to 3600, got '{}'", c.arg));
    if (c.verb == "set" && (c.arg.empty() || c.arg2.empty() || (std::strtod(c.arg2.c_str(), &end), *end)))
      fail(at, "set: expected a path and a number, e.g. 'set scene.mandelbox.scale 2.2'");
    auto whole = [](const std::string& t, int lo, int hi) {
      char* e = nullptr;
      const long n = std::strtol(t.c_str(), &e, 10);
      return !t.empty() && !*e && n >= lo && n <= hi;
    };
    if (c.verb == "hires" && !(whole(c.arg, 16, 16384) && whole(c.arg2, 16, 16384) && whole(c.arg3, 1, 1024)))
      fail(at, "hires: expected WIDTH HEIGHT SAMPLES (16 to 16384, and 1 to 1024), e.g. 'hires 1920 1080 16'");
    if (c.verb == "snap" && c.arg.empty()) fail(at, "snap: expected the PNG file to write");
    out.push_back(c);
  }
  return out;
}

void run_event_script(Viewer& v, SdlWindow& window, SceneSession& scene, const std::vector<ScriptCommand>& script) {
  for (const ScriptCommand& c : script) {
    if (c.verb == "quit") return;
    if (c.verb == "key") {
      auto [key, mod] = key_of(c.arg);
      SDL_Event e{};
      e.type = SDL_KEYDOWN;
      e.key.keysym.sym = key;
      e.key.keysym.mod = mod;
      e.key.state = SDL_PRESSED;
      SDL_PushEvent(&e);
      if (!v.step()) return;
    } else if (c.verb == "set") {
      v.live_values().set(c.arg, std::strtod(c.arg2.c_str(), nullptr));
      if (!v.step()) return;
    } else if (c.verb == "wait") {
      step_for(v, std::strtod(c.arg.c_str(), nullptr));
    } else if (c.verb == "settle") {
      settle(v, scene);
    } else if (c.verb == "hires") {
      v.tools().hires_width = std::atoi(c.arg.c_str());
      v.tools().hires_height = std::atoi(c.arg2.c_str());
      v.tools().hires_samples = std::atoi(c.arg3.c_str());
    } else if (c.verb == "snap") {
      snap(window, c.arg);
    }
  }
  v.run();
}

}  // namespace sdfc::viewer
