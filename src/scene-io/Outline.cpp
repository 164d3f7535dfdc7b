#include "Outline.h"

#include <algorithm>
#include <array>
#include <limits>

namespace prism::scene_io {

void sampleOutline(
    const float *xyz, size_t count, std::vector<scenes::Vec3> &outline)
{
  if (count == 0)
    return;
  auto at = [&](size_t v) {
    return scenes::Vec3{xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]};
  };
  // The support points: the vertex furthest along each direction.
  constexpr int kDirections = 26;
  std::array<scenes::Vec3, kDirections> directions;
  int d = 0;
  for (int x = -1; x <= 1; x++)
    for (int y = -1; y <= 1; y++)
      for (int z = -1; z <= 1; z++)
        if (x || y || z)
          directions[size_t(d++)] = {float(x), float(y), float(z)};
  std::array<size_t, kDirections> furthest{};
  std::array<float, kDirections> reach;
  reach.fill(-std::numeric_limits<float>::infinity());
  for (size_t v = 0; v < count; v++) {
    const scenes::Vec3 p = at(v);
    for (size_t i = 0; i < kDirections; i++) {
      const float r = scenes::dot(p, directions[i]);
      if (r > reach[i]) {
        reach[i] = r;
        furthest[i] = v;
      }
    }
  }
  for (size_t v : furthest)
    outline.push_back(at(v));
  // And an even sample, for shapes the 26 directions see only roughly.
  const size_t rest = kOutlinePerMesh - kDirections;
  const size_t stride = std::max<size_t>(1, (count + rest - 1) / rest);
  for (size_t v = 0; v < count; v += stride)
    outline.push_back(at(v));
}

} // namespace prism::scene_io
