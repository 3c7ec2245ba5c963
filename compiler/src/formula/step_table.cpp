// Every step a chain can name.
#include "by_name.hpp"
#include "sdfc/formula/step.hpp"

namespace sdfc::formula {

extern const StepDef kBoxFold, kSphereFold, kAbs, kPlaneFold, kOctaFold, kTetraFold, kMengerFold;
extern const StepDef kRotate, kScale, kScaleXYZ, kTranslate, kAddC, kBulbPower, kExpr;
extern const StepDef kSphericalInvert, kKleinianFold, kSurfFold, kPolyfold, kIcosaFold;
extern const StepDef kWrap, kKleinianFlip;
extern const StepDef kQuaternion, kHypercomplex, kQuadray, kAexion;  // 4-D
extern const StepDef kPolyhedralFold, kTriplexNewton;

const std::vector<const StepDef*>& steps() {
  static const std::vector<const StepDef*> all = sorted_by_name<StepDef>(
      {&kAbs, &kAddC, &kBoxFold, &kBulbPower, &kExpr, &kMengerFold, &kOctaFold, &kPlaneFold, &kRotate, &kScale, &kScaleXYZ,
       &kSphereFold, &kTetraFold, &kTranslate, &kSphericalInvert, &kKleinianFold, &kSurfFold, &kPolyfold, &kIcosaFold,
       &kWrap, &kKleinianFlip,
       &kQuaternion, &kHypercomplex, &kQuadray, &kAexion, &kPolyhedralFold, &kTriplexNewton});
  return all;
}

const StepDef* find_step(std::string_view name) { return find_by_name(steps(), name); }

}  // namespace sdfc::formula
