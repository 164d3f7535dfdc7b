#include "Scene.h"

#include <algorithm>

namespace prism::scenes {

bool Bounds::empty() const
{
  return !(
      lower[0] <= upper[0] && lower[1] <= upper[1] && lower[2] <= upper[2]);
}

void Bounds::extend(const Vec3 &point)
{
  for (int i = 0; i < 3; i++) {
    lower[i] = std::min(lower[i], point[i]);
    upper[i] = std::max(upper[i], point[i]);
  }
}

void Bounds::extend(const Bounds &other)
{
  if (other.empty())
    return;
  extend(other.lower);
  extend(other.upper);
}

void releaseScene(ANARIDevice device, Scene &scene)
{
  for (ANARILight light : scene.lights)
    anariRelease(device, light);
  scene.lights.clear();
  if (scene.world)
    anariRelease(device, scene.world);
  scene.world = nullptr;
}

} // namespace prism::scenes
