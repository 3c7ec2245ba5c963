// Every preset, by name.
#include <algorithm>

#include "sdfc/formula/preset.hpp"

namespace sdfc::formula {

extern const Preset kMandelbulbPreset, kMandelboxPreset, kMengerPreset, kSierpinskiPreset, kKifsPreset;
extern const Preset kBulbPower2Preset, kPseudoKleinianPreset, kAmazingSurfPreset, kBoxFoldBulbPow2Preset;

const std::vector<const Preset*>& presets() {
  static const std::vector<const Preset*> all = [] {
    std::vector<const Preset*> v{&kMandelbulbPreset, &kMandelboxPreset,      &kMengerPreset,      &kSierpinskiPreset,
                                 &kKifsPreset,       &kBulbPower2Preset,     &kPseudoKleinianPreset, &kAmazingSurfPreset,
                                 &kBoxFoldBulbPow2Preset};
    std::sort(v.begin(), v.end(), [](auto* a, auto* b) { return a->name < b->name; });
    return v;
  }();
  return all;
}

const Preset* find_preset(std::string_view name) {
  for (const Preset* p : presets())
    if (p->name == name) return p;
  return nullptr;
}

}  // namespace sdfc::formula
