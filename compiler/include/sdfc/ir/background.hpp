#pragma once
// What a ray that hits nothing sees: a gradient from bottom to top, an
// analytic daylight sky or an environment map (`background:` in a scene).
#include <array>
#include <memory>
#include <string>
#include <vector>

namespace sdfc::ir {

using Vec3d = std::array<double, 3>;

// An analytic daylight sky (`background: {sky: ...}`): colours
// derived on the host from the sun's elevation and the turbidity
// (sky_model.cpp); the sun itself is a directional light in `lights`.
struct Sky {
  bool enabled = false;
  Vec3d sun_direction{0.4, -0.3, 0.6};  // towards the sun (unit)
  double turbidity = 3;                 // 2 (clear) ... 10 (hazy)
  double sun_intensity = 2.5;
  Vec3d zenith{}, horizon{}, ground{}, glow{};  // derived
  double glow_power = 8;                        // derived: the halo's falloff
};

// An equirectangular environment map (`background: {map: ...}`),
// lighting the path integrator. The pixels and their sampling tables are
// loaded by the front end (environment_map.cpp) and reach the kernel as a
// buffer argument; the file name never does.
struct EnvironmentMap {
  bool enabled = false;
  std::string file;         // as the scene wrote it, for messages
  double rotation = 0;      // degrees about the up axis, counter-clockwise seen from above
  double intensity = 1;     // scales the map's values
  bool visible = true;      // camera rays see the map; false: they see top/bottom
  bool importance = true;   // sampling: importance (luminance x sin theta) or uniform
  int width = 0, height = 0;
  // rgb (width x height, top row first, times intensity), then the marginal
  // CDF over rows (height + 1), then one CDF per row (width + 1 each).
  std::shared_ptr<const std::vector<float>> data;
};

struct Background {
  Vec3d top{0.45, 0.55, 0.7};
  Vec3d bottom{0.15, 0.17, 0.22};
  Sky sky;
  EnvironmentMap map;
};

}  // namespace sdfc::ir
