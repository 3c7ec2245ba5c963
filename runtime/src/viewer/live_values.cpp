#include "viewer/live_values.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "sdfc/compile.hpp"
#include "sdfc/source/write_back.hpp"
#include "sdfc/source/write_section.hpp"
#include "sdfc/source/yaml_loader.hpp"
#include "sdfc/support/diagnostics.hpp"

namespace sdfc::viewer {

namespace {
std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

std::string dotted_path(const std::string& path) {
  std::string out;
  for (char c : path) {
    if (c == ']') continue;
    out += c == '[' ? '.' : c;
  }
  return out;
}

LiveValues::LiveValues(SceneSession& scene)
    : scene_(scene), base_sets_(scene.options().sets), text_(read_all(scene.options().path)),
      root_(load_yaml_text(text_, scene.options().path)) {
  for (const auto& s : scene.slots()) unlocked_.push_back(dotted_path(s->path));
}

double LiveValues::file_value(const std::string& path) const {
  const SourceValue* v = find_value(root_, path);
  if (v && v->is_scalar() && (v->scalar == "true" || v->scalar == "false")) return v->scalar == "true";
  return v && v->is_scalar() ? std::strtod(v->scalar.c_str(), nullptr) : 0.0;
}

std::string LiveValues::text_of(const std::string& path, double v) const {
  if (bools_.count(path)) return v != 0 ? "true" : "false";
  return yaml_number(v);
}

double LiveValues::value(const std::string& path) const {
  const std::string p = dotted_path(path);
  auto it = edits_.find(p);
  return it != edits_.end() ? it->second : file_value(p);
}

bool LiveValues::changed(const std::string& path) const {
  auto it = edits_.find(dotted_path(path));
  return it != edits_.end() && file_value(it->first) != it->second;
}

bool LiveValues::changed_under(const std::string& path) const {
  const std::string prefix = dotted_path(path) + ".";
  for (auto it = edits_.lower_bound(prefix); it != edits_.end() && it->first.compare(0, prefix.size(), prefix) == 0; ++it)
    if (changed(it->first)) return true;
  return false;
}

std::vector<std::string> LiveValues::overrides() const {
  std::vector<std::string> out = base_sets_;
  for (const auto& [p, v] : edits_) out.push_back(p + "=" + text_of(p, v));
  return out;
}

SceneOptions LiveValues::options_with(const std::vector<std::string>& unlock) const {
  SceneOptions o = scene_.options();
  o.sets = overrides();
  o.unlocks.clear();
  for (const auto& p : unlock) {
    auto it = can_unlock_.find(p);
    std::optional<std::pair<double, double>> range;
    if (it != can_unlock_.end() && it->second && *it->second) {  // the narrow range, around the value now
      const double x = value(p);
      range = std::make_pair(std::min(x * 0.75, x * 1.25), std::max(x * 0.75, x * 1.25));
    }
    o.unlocks.push_back({p, range});
  }
  return o;
}

bool LiveValues::unlockable(const std::string& path) const {
  auto& known = const_cast<LiveValues*>(this)->can_unlock_;
  if (auto it = known.find(path); it != known.end()) return it->second.has_value();
  // The front end alone says whether a run-time reader takes it (no kernel build).
  auto accepted = [&](std::optional<std::pair<double, double>> range) {
    try {
      SourceValue doc = load_scene_source(scene_.options().path, overrides());
      mark_unlocked(doc, {{path, range}});
      build_module(doc, scene_.options().path);
      return true;
    } catch (const SceneError&) {
      return false;
    }
  };
  const double x = value(path);
  const std::pair<double, double> narrow{std::min(x * 0.75, x * 1.25), std::max(x * 0.75, x * 1.25)};
  auto& entry = known[path];
  if (accepted(std::nullopt)) entry = std::optional<std::pair<double, double>>{};
  else if (x != 0 && accepted(narrow)) entry = std::optional<std::pair<double, double>>{narrow};
  return entry.has_value();
}

LiveValues::Change LiveValues::apply(const std::string& path, double value) {
  edits_[path] = value;
  last_change_ = std::chrono::steady_clock::now();
  for (const auto& s : scene_.slots())
    if (dotted_path(s->path) == path && value >= s->lo && value <= s->hi) {
      scene_.set_slot(s->index, value);
      return Change::Frame;
    }
  const bool pending = std::find(unlocked_.begin(), unlocked_.end(), path) != unlocked_.end() && scene_.building();
  if (pending) return Change::Unlocking;  // poll() gives the new slot this value
  if (!bools_.count(path) && unlockable(path)) {
    if (std::find(unlocked_.begin(), unlocked_.end(), path) == unlocked_.end()) unlocked_.push_back(path);
    scene_.rebuild_in_background(options_with(unlocked_));
    return Change::Unlocking;
  }
  scene_.rebuild_in_background(options_with(unlocked_));
  return Change::Rebuilding;
}

LiveValues::Change LiveValues::set(const std::string& path, double v) {
  const std::string p = dotted_path(path);
  const double before = value(p);
  if (!done_.empty() && done_.back().path == p)
    done_.back().after = v;  // one drag of one slider is one undo step
  else
    done_.push_back({p, before, v});
  undone_.clear();
  return apply(p, v);
}

LiveValues::Change LiveValues::set_bool(const std::string& path, bool v) {
  bools_.insert(dotted_path(path));
  return set(path, v ? 1 : 0);
}

ReloadResult LiveValues::poll() {
  ReloadResult r = scene_.adopt_build();
  if (r != ReloadResult::Reloaded) return r;
  last_change_ = std::chrono::steady_clock::now();  // the quiet time before baking counts from the new kernel
  for (const auto& s : scene_.slots())
    if (auto it = edits_.find(dotted_path(s->path)); it != edits_.end() && it->second >= s->lo && it->second <= s->hi)
      scene_.set_slot(s->index, it->second);
  return r;
}

void LiveValues::bake() {
  unlocked_.clear();
  scene_.rebuild_in_background(options_with({}));
}

bool LiveValues::undo() {
  if (done_.empty()) return false;
  Step s = done_.back();
  done_.pop_back();
  undone_.push_back(s);
  apply(s.path, s.before);
  return true;
}

bool LiveValues::redo() {
  if (undone_.empty()) return false;
  Step s = undone_.back();
  undone_.pop_back();
  done_.push_back(s);
  apply(s.path, s.after);
  return true;
}

LiveValues::Saved LiveValues::save(bool overwrite) {
  const std::string& path = scene_.options().path;
  std::vector<ValueEdit> edits;
  for (const auto& [p, v] : edits_)
    if (changed(p)) edits.push_back({p, text_of(p, v)});
  if (edits.empty()) return Saved::NothingToSave;
  const std::string text = rewrite_values(text_, load_yaml_text(text_, path), edits);
  if (!save_if_unchanged(path, overwrite ? read_all(path) : text_, text)) return Saved::ChangedOnDisk;
  adopt_text(text);
  return Saved::Written;
}

LiveValues::Saved LiveValues::save_section(const std::string& key, const std::string& block) {
  const std::string& path = scene_.options().path;
  const std::string text = replace_section(text_, root_, key, block);
  if (text == text_) return Saved::NothingToSave;
  if (!save_if_unchanged(path, text_, text)) return Saved::ChangedOnDisk;
  adopt_text(text);
  return Saved::Written;
}

void LiveValues::adopt_text(std::string text) {
  text_ = std::move(text);
  root_ = load_yaml_text(text_, scene_.options().path);
  scene_.note_own_save();
}

}  // namespace sdfc::viewer
