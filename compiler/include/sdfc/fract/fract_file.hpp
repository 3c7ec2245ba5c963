#pragma once
// Mandelbulber's settings files (.fract), read as they are written: a
// header, `[main_parameters]`, `[fractal_1]` ... `[fractal_9]`, and the
// `[frames]` / `[keyframes]` tables of an animation. Values stay text here
// (with their place in the file); fract_params.hpp reads them as numbers,
// vectors, colours and gradients, with Mandelbulber's defaults.
#include <array>
#include <map>
#include <string>
#include <vector>

#include "sdfc/support/diagnostics.hpp"

namespace sdfc::fract {

struct Entry {
  std::string value;  // as written, without the `;`
  SourceLoc loc;      // the key
  SourceLoc value_loc;
};

struct Section {
  bool present = false;
  SourceLoc loc;
  std::map<std::string, Entry> entries;  // by the key's current (2.20) name
};

// An animation table: `frame;key_x;key_y;...` then one `;`-separated row per frame.
struct Table {
  bool present = false;
  SourceLoc loc;
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
  std::vector<SourceLoc> row_locs;
};

constexpr int kFractalSlots = 9;

struct File {
  std::string name;
  double version = 0;  // from `# version 2.20`
  SourceLoc version_loc;
  bool only_modified = false;
  Section main;
  std::array<Section, kFractalSlots> fractal;  // [fractal_1] is fractal[0]
  Table frames, keyframes;
};

// The first line of every file Mandelbulber writes.
inline constexpr const char* kHeader = "# Mandelbulber settings file";

// Throws SceneError (file:line:column) for a file that is not a settings
// file or that is broken: a line outside a section, a key without a value or
// `;`, an unknown section, a repeated key, a table row of the wrong width.
File parse_text(const std::string& text, const std::string& name);
File read_file(const std::string& path);

// Whether `path` names a .fract file: by its extension, or by its first line.
bool is_fract_path(const std::string& path);

// The name a key had before `version`'s renames, or the key itself: older
// files are read under the names Mandelbulber 2.20 uses.
std::string current_key_name(const std::string& key, double version);

}  // namespace sdfc::fract
