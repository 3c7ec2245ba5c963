#include "viewer/param_panel.hpp"

#include <SDL.h>
#include <fmt/format.h>
#include <imgui.h>
#include <imgui_impl_sdl.h>
#include <imgui_impl_sdlrenderer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>

#include "sdfc/support/diagnostics.hpp"

namespace sdfc::viewer {

namespace {
bool numeric(const SourceValue& v, double* x) {
  if (!v.is_scalar() || v.quoted || v.scalar.empty()) return false;
  char* end = nullptr;
  *x = std::strtod(v.scalar.c_str(), &end);
  return end == v.scalar.c_str() + v.scalar.size() && std::isfinite(*x);
}
bool whole(const std::string& s) { return s.find_first_of(".eE") == std::string::npos; }
std::string join(const std::string& path, const std::string& step) { return path.empty() ? step : path + "." + step; }
}  // namespace

ParamPanel::ParamPanel(SDL_Window* window, SDL_Renderer* renderer, LiveValues& live, SceneSession& scene)
    : live_(live), scene_(scene) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini beside the user's scene
  ImGui::StyleColorsDark();
  ImGui_ImplSDL2_InitForSDLRenderer(window);
  ImGui_ImplSDLRenderer_Init(renderer);
}

ParamPanel::~ParamPanel() {
  ImGui_ImplSDLRenderer_Shutdown();
  ImGui_ImplSDL2_Shutdown();
  ImGui::DestroyContext();
}

bool ParamPanel::handle(const SDL_Event& e) {
  ImGui_ImplSDL2_ProcessEvent(&e);
  const ImGuiIO& io = ImGui::GetIO();
  const bool mouse = e.type == SDL_MOUSEMOTION || e.type == SDL_MOUSEBUTTONDOWN || e.type == SDL_MOUSEBUTTONUP ||
                     e.type == SDL_MOUSEWHEEL;
  if (e.type == SDL_KEYDOWN && (e.key.keysym.mod & KMOD_CTRL) && !io.WantTextInput) {
    switch (e.key.keysym.sym) {
      case SDLK_z: changed_ = live_.undo() || changed_; return true;
      case SDLK_y: changed_ = live_.redo() || changed_; return true;
      case SDLK_s: save(); return true;
      default: break;
    }
  }
  return (mouse && io.WantCaptureMouse) || ((e.type == SDL_KEYDOWN || e.type == SDL_TEXTINPUT) && io.WantTextInput);
}

void ParamPanel::touched(LiveValues::Change c) {
  changed_ = true;
  confirm_overwrite_ = false;
  if (c == LiveValues::Change::Unlocking) status_ = "building (unlocking the value)...";
  if (c == LiveValues::Change::Rebuilding) status_ = "building (this value shapes the code)...";
}

bool ParamPanel::take_change() {
  if (live_.poll() == ReloadResult::Reloaded) {
    status_ = fmt::format("kernel #{} built in {:.0f} ms{}", scene_.generation(), scene_.last_build_ms(),
                          live_.unlocked_now() ? fmt::format(", {} value(s) live", scene_.slots().size()) : ", baked");
    changed_ = true;
  } else if (!scene_.building() && !scene_.error().empty() && status_.rfind("building", 0) == 0) {
    status_ = "build failed: " + scene_.error().substr(0, scene_.error().find('\n'));
  }
  bool c = changed_;
  changed_ = false;
  return c;
}

void ParamPanel::idle_bake() {
  const double idle = std::chrono::duration<double>(std::chrono::steady_clock::now() - live_.last_change()).count();
  if (live_.unlocked_now() && !scene_.building() && idle > kIdleBakeSeconds) {
    live_.bake();
    status_ = "building (baking the values for speed)...";
  }
}

void ParamPanel::save() {
  try {
    switch (live_.save(confirm_overwrite_)) {
      case LiveValues::Saved::Written: status_ = "saved " + scene_.options().path; confirm_overwrite_ = false; break;
      case LiveValues::Saved::NothingToSave: status_ = "nothing changed"; break;
      case LiveValues::Saved::ChangedOnDisk:
        status_ = "the file changed on disk since it was loaded: save again to overwrite it";
        confirm_overwrite_ = true;
        break;
    }
  } catch (const std::exception& e) {
    status_ = std::string("save failed: ") + e.what();
  }
}

void ParamPanel::number(const std::string& label, const std::string& path, const SourceValue& v) {
  float x = static_cast<float>(live_.value(path));
  const bool changed = live_.changed(path);
  if (changed) ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 220, 80, 255));
  const UnlockSlot* slot = nullptr;
  for (const auto& s : scene_.slots())
    if (dotted_path(s->path) == path) slot = s.get();
  bool edited = false;
  ImGui::PushID(path.c_str());
  if (slot) {
    edited = ImGui::SliderFloat(label.c_str(), &x, float(slot->lo), float(slot->hi), "%.4g");
  } else if (whole(v.scalar) && !live_.unlockable(path)) {
    int i = static_cast<int>(x);
    edited = ImGui::DragInt(label.c_str(), &i, 0.1f);
    x = float(i);
  } else {
    edited = ImGui::DragFloat(label.c_str(), &x, std::max(std::fabs(x), 1.0f) * 0.005f, 0, 0, "%.4g");
  }
  ImGui::PopID();
  if (changed) ImGui::PopStyleColor();
  if (edited) touched(live_.set(path, double(x)));
}

void ParamPanel::colour(const std::string& label, const std::string& path) {
  float c[3];
  bool changed = false;
  for (int i = 0; i < 3; ++i) {
    c[i] = static_cast<float>(live_.value(join(path, std::to_string(i))));
    changed = changed || live_.changed(join(path, std::to_string(i)));
  }
  if (changed) ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 220, 80, 255));
  ImGui::PushID(path.c_str());
  const bool edited = ImGui::ColorEdit3(label.c_str(), c, ImGuiColorEditFlags_Float);
  ImGui::PopID();
  if (changed) ImGui::PopStyleColor();
  if (edited)
    for (int i = 0; i < 3; ++i)
      if (float(live_.value(join(path, std::to_string(i)))) != c[i]) touched(live_.set(join(path, std::to_string(i)), c[i]));
}

void ParamPanel::tree(const SourceValue& v, const std::string& path) {
  auto item = [&](const std::string& label, const std::string& p, const SourceValue& child) {
    double x = 0;
    const bool colour3 = child.is_seq() && child.items.size() == 3 && label.find("color") != std::string::npos &&
                         std::all_of(child.items.begin(), child.items.end(), [&](const SourceValue& i) { return numeric(i, &x); });
    if (numeric(child, &x)) {
      number(label, p, child);
    } else if (colour3) {
      colour(label, p);
    } else if (child.is_map() || child.is_seq()) {
      if (ImGui::TreeNode(p.c_str(), "%s  (line %d)", label.c_str(), child.loc.line)) {
        tree(child, p);
        ImGui::TreePop();
      }
    } else if (child.is_scalar()) {
      ImGui::TextDisabled("%s: %s", label.c_str(), child.scalar.c_str());  // words and expressions: edit the file
    }
  };
  for (const auto& [k, child] : v.entries) item(k.scalar, join(path, k.scalar), child);
  for (size_t i = 0; i < v.items.size(); ++i) item(fmt::format("[{}]", i), join(path, std::to_string(i)), v.items[i]);
}

void ParamPanel::draw() {
  ImGui_ImplSDLRenderer_NewFrame();
  ImGui_ImplSDL2_NewFrame();
  ImGui::NewFrame();
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(380, 460), ImGuiCond_FirstUseEver);
  ImGui::Begin("Scene");
  if (ImGui::Button("Save")) save();
  ImGui::SameLine();
  if (ImGui::Button("Undo") && live_.undo()) changed_ = true;
  ImGui::SameLine();
  if (ImGui::Button("Redo") && live_.redo()) changed_ = true;
  ImGui::SameLine();
  if (ImGui::Button("Bake")) live_.bake(), status_ = "building (baking the values for speed)...";
  ImGui::TextWrapped("%s", (scene_.building() && status_.empty() ? "building..." : status_).c_str());
  ImGui::Separator();
  tree(live_.file(), "");
  ImGui::End();
  ImGui::Render();
  ImGui_ImplSDLRenderer_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace sdfc::viewer
