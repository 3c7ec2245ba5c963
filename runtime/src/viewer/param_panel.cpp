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
#include <string_view>
#include <vector>

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
const ImU32 kChanged = IM_COL32(255, 220, 80, 255);  // a value that differs from the file
// A node with at most this many values starts open (a light, a primitive); larger ones closed.
constexpr int kOpenUpTo = 12;
int values_in(const SourceValue& v) {
  int n = v.is_scalar();
  for (const auto& i : v.items) n += values_in(i);
  for (const auto& [k, e] : v.entries) n += values_in(e);
  return n;
}
std::string join(const std::string& path, const std::string& step) { return path.empty() ? step : path + "." + step; }
}  // namespace

ParamPanel::ParamPanel(SDL_Window* window, SDL_Renderer* renderer, LiveValues& live, SceneSession& scene, ViewTools& tools)
    : live_(live), scene_(scene), tools_(tools) {
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
  if (changed) ImGui::PushStyleColor(ImGuiCol_Text, kChanged);
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

// Three numbers on one row: a colour picker for a colour, else three drag fields.
void ParamPanel::triple(const std::string& label, const std::string& path, bool colour) {
  float c[3];
  bool changed = false;
  for (int i = 0; i < 3; ++i) {
    c[i] = static_cast<float>(live_.value(join(path, std::to_string(i))));
    changed = changed || live_.changed(join(path, std::to_string(i)));
  }
  if (changed) ImGui::PushStyleColor(ImGuiCol_Text, kChanged);
  ImGui::PushID(path.c_str());
  const float speed = std::max({std::fabs(c[0]), std::fabs(c[1]), std::fabs(c[2]), 1.0f}) * 0.005f;
  const bool edited = colour ? ImGui::ColorEdit3(label.c_str(), c, ImGuiColorEditFlags_Float)
                             : ImGui::DragFloat3(label.c_str(), c, speed, 0, 0, "%.4g");
  ImGui::PopID();
  if (changed) ImGui::PopStyleColor();
  if (edited)
    for (int i = 0; i < 3; ++i)
      if (float(live_.value(join(path, std::to_string(i)))) != c[i]) touched(live_.set(join(path, std::to_string(i)), c[i]));
}

void ParamPanel::checkbox(const std::string& label, const std::string& path) {
  bool on = live_.value(path) != 0;
  const bool changed = live_.changed(path);
  if (changed) ImGui::PushStyleColor(ImGuiCol_Text, kChanged);
  ImGui::PushID(path.c_str());
  const bool edited = ImGui::Checkbox(label.c_str(), &on);
  ImGui::PopID();
  if (changed) ImGui::PopStyleColor();
  if (edited) touched(live_.set_bool(path, on));
}

void ParamPanel::entry(const std::string& label, const std::string& p, const SourceValue& child) {
  double x = 0;
  const bool three = child.is_seq() && child.items.size() == 3 &&
                     std::all_of(child.items.begin(), child.items.end(), [&](const SourceValue& i) { return numeric(i, &x); });
  if (numeric(child, &x)) {
    number(label, p, child);
  } else if (three) {
    triple(label, p, label.find("color") != std::string::npos);
  } else if (child.is_scalar() && !child.quoted && (child.scalar == "true" || child.scalar == "false")) {
    checkbox(label, p);
  } else if (child.is_map() || child.is_seq()) {
    const ImGuiTreeNodeFlags open = values_in(child) <= kOpenUpTo ? ImGuiTreeNodeFlags_DefaultOpen : 0;
    if (live_.changed_under(p)) ImGui::SetNextItemOpen(true);  // a changed value stays in sight
    if (ImGui::TreeNodeEx(p.c_str(), open, "%s  (line %d)", label.c_str(), child.loc.line)) {
      tree(child, p);
      ImGui::TreePop();
    }
  } else if (child.is_scalar()) {
    ImGui::TextDisabled("%s: %s", label.c_str(), child.scalar.c_str());  // words and expressions: edit the file
  }
}

void ParamPanel::tree(const SourceValue& v, const std::string& path) {
  for (const auto& [k, child] : v.entries) entry(k.scalar, join(path, k.scalar), child);
  for (size_t i = 0; i < v.items.size(); ++i) entry(fmt::format("[{}]", i), join(path, std::to_string(i)), v.items[i]);
}

// The file's top-level keys grouped as people look for them, whatever their order in the file.
void ParamPanel::sections() {
  struct Section {
    const char* title;
    std::vector<std::string_view> keys;
  };
  static const Section kSections[] = {{"Scene", {"scene"}},
                                      {"Camera", {"camera"}},
                                      {"Lights", {"lights"}},
                                      {"Materials", {"materials"}},
                                      {"Effects", {"effects", "render", "background"}}};
  const SourceValue& file = live_.file();
  auto listed = [&](std::string_view key) {
    for (const auto& s : kSections)
      if (std::find(s.keys.begin(), s.keys.end(), key) != s.keys.end()) return true;
    return key == "bookmarks";  // shown in the camera section
  };
  for (const auto& s : kSections) {
    const bool camera = std::string_view(s.title) == "Camera";
    const bool present = std::any_of(s.keys.begin(), s.keys.end(), [&](std::string_view k) { return file.find(k); });
    if (!present && !camera) continue;
    if (!ImGui::CollapsingHeader(s.title, camera || s.keys.front() == "scene" ? ImGuiTreeNodeFlags_DefaultOpen : 0)) continue;
    if (camera && draw_view_tools(tools_)) changed_ = true;
    for (std::string_view k : s.keys) {
      const SourceValue* v = file.find(k);
      if (!v) continue;
      if (k == "scene") ImGui::SetNextItemOpen(true, ImGuiCond_Once);  // the root node (a union of many) starts open
      if (s.keys.size() == 1 && v->is_map() && !camera) tree(*v, std::string(k));  // the section is the key: no second level
      else if (!camera) entry(std::string(k), std::string(k), *v);
      else ImGui::SetNextItemOpen(false, ImGuiCond_Once), entry("in the file", "camera", *v);  // the view above moves apart from it
    }
  }
  std::vector<const std::pair<SourceValue, SourceValue>*> rest;
  for (const auto& e : file.entries)
    if (!listed(e.first.scalar)) rest.push_back(&e);
  if (!rest.empty() && ImGui::CollapsingHeader("Other"))
    for (const auto* e : rest) entry(e->first.scalar, e->first.scalar, e->second);
}

void ParamPanel::draw() {
  ImGui_ImplSDLRenderer_NewFrame();
  ImGui_ImplSDL2_NewFrame();
  ImGui::NewFrame();
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  const float tall = ImGui::GetIO().DisplaySize.y - 16;
  ImGui::SetNextWindowSize(ImVec2(400, std::clamp(tall, 200.0f, 720.0f)), ImGuiCond_FirstUseEver);
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
  sections();
  ImGui::End();
  ImGui::Render();
  ImGui_ImplSDLRenderer_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace sdfc::viewer
