#pragma once
// Reference (double, CPU) distance estimators for the fractal kinds of
// issue 3, written from the formulas with plain branches and full
// quaternion/complex arithmetic, independently of the OpenCL stdlib.
#include <array>
#include <vector>

namespace sdfc::reference::fractals {

using Vec3 = std::array<double, 3>;

double juliabulb(const Vec3& p, const std::vector<double>& q);
double mandelbox(const Vec3& p, const std::vector<double>& q);
double quaternion_julia(const Vec3& p, const std::vector<double>& q);
double menger(const Vec3& p, const std::vector<double>& q);
double sierpinski(const Vec3& p, const std::vector<double>& q);
double kifs(const Vec3& p, const std::vector<double>& q);
double hybrid(const Vec3& p, const std::vector<double>& q);

}  // namespace sdfc::reference::fractals
