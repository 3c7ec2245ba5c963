// Every preset, by name.
#include "by_name.hpp"
#include "sdfc/formula/preset.hpp"

namespace sdfc::formula {

extern const Preset kMandelbulbPreset, kMandelboxPreset, kMengerPreset, kSierpinskiPreset, kKifsPreset;
extern const Preset kBulbPower2Preset, kPseudoKleinianPreset, kAmazingSurfPreset, kBoxFoldBulbPow2Preset;
extern const Preset kXenodreambuiePreset, kEiffieMsltoePreset, kKochPreset;
extern const Preset kHybridPreset;
extern const Preset kGeneralizedFoldBoxPreset;
extern const Preset kAboxMod11Preset, kAmazingSurfMod2Preset, kAmazingSurfMod4Preset, kAboxMod15Preset;
extern const Preset kMengerMod1Preset, kMengerSmoothPreset, kMenger3Preset, kMengerCrossKifsPreset;
extern const Preset kJosKleinianPreset;
extern const Preset kJuliaPreset, kQuaternionPreset, kHypercomplexPreset, kAexionPreset;
extern const Preset kAmazingIfsPreset, kNewtonPow3Preset;

const std::vector<const Preset*>& presets() {
  static const std::vector<const Preset*> all =
      sorted_by_name<Preset>({&kMandelbulbPreset, &kMandelboxPreset, &kMengerPreset, &kSierpinskiPreset, &kKifsPreset,
                              &kBulbPower2Preset, &kPseudoKleinianPreset, &kAmazingSurfPreset, &kBoxFoldBulbPow2Preset,
                              &kXenodreambuiePreset, &kEiffieMsltoePreset, &kKochPreset,
                              &kHybridPreset,
                              &kGeneralizedFoldBoxPreset,
                              &kAboxMod11Preset, &kAmazingSurfMod2Preset, &kAmazingSurfMod4Preset, &kAboxMod15Preset,
                              &kMengerMod1Preset, &kMengerSmoothPreset, &kMenger3Preset, &kMengerCrossKifsPreset,
                              &kJosKleinianPreset,
                              &kJuliaPreset, &kQuaternionPreset, &kHypercomplexPreset, &kAexionPreset,
                              &kAmazingIfsPreset, &kNewtonPow3Preset});
  return all;
}

const Preset* find_preset(std::string_view name) { return find_by_name(presets(), name); }

}  // namespace sdfc::formula
