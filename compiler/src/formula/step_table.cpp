// Every step a chain can name.
#include <algorithm>

#include "sdfc/formula/step.hpp"

namespace sdfc::formula {

extern const StepDef kBoxFold, kSphereFold, kAbs, kPlaneFold, kOctaFold, kTetraFold, kMengerFold;
extern const StepDef kRotate, kScale, kScaleXYZ, kTranslate, kAddC, kBulbPower, kExpr;
extern const StepDef kSphericalInvert, kKleinianFold, kSurfFold, kPolyfold, kIcosaFold;

const std::vector<const StepDef*>& steps() {
  static const std::vector<const StepDef*> all = [] {
    std::vector<const StepDef*> v{&kAbs,       &kAddC,   &kBoxFold, &kBulbPower, &kExpr,      &kMengerFold, &kOctaFold,
                                  &kPlaneFold, &kRotate, &kScale,   &kScaleXYZ,  &kSphereFold, &kTetraFold, &kTranslate,
                                  &kSphericalInvert, &kKleinianFold, &kSurfFold, &kPolyfold, &kIcosaFold};
    std::sort(v.begin(), v.end(), [](auto* a, auto* b) { return a->name < b->name; });
    return v;
  }();
  return all;
}

const StepDef* find_step(std::string_view name) {
  for (const StepDef* d : steps())
    if (d->name == name) return d;
  return nullptr;
}

}  // namespace sdfc::formula
