// background.sky: an analytic daylight sky. Its colours come
// from the sun's elevation and the turbidity here, on the host, so the
// kernel's shade_sky only blends them: the sun's colour is the light left
// after Rayleigh extinction (per channel) and haze (grey) along the air
// mass of its elevation (Kasten and Young's formula); the zenith is blue and
// dims as the sun sets, the horizon whitens with haze and warms towards the
// sun's colour when it is low. An estimate in the spirit of Preetham's
// model, not a spectral simulation.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "read_transport.hpp"

namespace sdfc::frontend {

namespace {

double smoothstep(double a, double b, double x) {
  double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

}  // namespace

void read_sky(ValueReader& r, const SourceValue& v, ir::Background& bg) {
  MapReader m(r, v, "background.sky", {"sun_direction", "turbidity", "sun_intensity"});
  ir::Sky& sky = bg.sky;
  sky.enabled = true;
  sky.sun_direction = m.direction("sun_direction", sky.sun_direction);
  sky.turbidity = m.number("turbidity", sky.turbidity, Range::closed(1.7, 10));
  sky.sun_intensity = m.number("sun_intensity", 1.2, Range::non_negative(1e4));  // with the sky's light, a lit face near white
}

void add_sun(ir::RenderPlan& plan) {
  ir::Sky& sky = plan.background.sky;
  if (!sky.enabled) return;
  const ir::Vec3d& s = sky.sun_direction;
  const ir::Vec3d& up = plan.camera.up;
  const double h = std::clamp(s[0] * up[0] + s[1] * up[1] + s[2] * up[2], -1.0, 1.0);  // sine of the elevation
  const double deg = std::asin(h) * 180 / std::numbers::pi;
  const double air_mass = 1.0 / (std::max(h, 0.0) + 0.50572 * std::pow(std::max(deg, 0.0) + 6.07995, -1.6364));
  const double haze = (sky.turbidity - 1.7) / 8.3;  // 0 clear ... 1 hazy
  const ir::Vec3d rayleigh{0.05, 0.11, 0.26};       // optical depths at the zenith: red, green, blue
  ir::Vec3d sun;
  for (int i = 0; i < 3; ++i) sun[i] = std::exp(-(rayleigh[i] + 0.04 * (sky.turbidity - 1)) * air_mass);
  const double day = 0.08 + 0.92 * smoothstep(-0.1, 0.45, h);  // the sky dims as the sun sets
  const double low = 1 - smoothstep(0.0, 0.5, h);              // how much the horizon takes the sun's colour
  const ir::Vec3d blue{0.2, 0.4, 0.85}, pale{0.72, 0.8, 0.92};
  for (int i = 0; i < 3; ++i) {
    double grey = (blue[0] + blue[1] + blue[2]) / 3;
    sky.zenith[i] = day * (blue[i] + (grey - blue[i]) * 0.6 * haze);
    double horizon = pale[i] + (0.85 - pale[i]) * haze;
    sky.horizon[i] = day * (horizon + (sun[i] - horizon) * 0.45 * low);
    sky.ground[i] = 0.3 * sky.horizon[i];
    sky.glow[i] = day * sun[i] * (0.15 + 0.06 * sky.turbidity);
  }
  sky.glow_power = 14 - sky.turbidity;  // hazier: a wider halo
  plan.background.top = sky.zenith;
  plan.background.bottom = sky.ground;
  // the sun: a directional light that fades out as it sets
  ir::Light l;
  l.kind = ir::LightKind::Directional;
  l.direction = {-s[0], -s[1], -s[2]};
  l.color = sun;
  l.intensity = sky.sun_intensity * smoothstep(-0.03, 0.03, h);
  l.shadows = ir::Light::Shadows::Hard;
  l.loc = {};
  plan.lights.push_back(l);
}

}  // namespace sdfc::frontend
