// Named color maps for volume transfer functions, each a handful of
// published control values (sRGB, evenly spaced from low to high values).
#pragma once

#include "Scene.h"

#include <string>
#include <vector>

namespace prism::scenes {

struct ColorMap
{
  const char *name;
  std::vector<Vec3> srgbControlPoints; // evenly spaced over the value range
};

// Every named map, the default (coolwarm) first.
const std::vector<ColorMap> &colorMaps();
// The map called `name` (lower case), or nullptr.
const ColorMap *findColorMap(const std::string &name);
// "coolwarm, viridis, ...", for messages and --help.
std::string colorMapNames();
// The control points as linear RGB, what renderers add up: an sRGB-encoded
// image then shows the published colors.
std::vector<Vec3> linearColors(const ColorMap &map);

} // namespace prism::scenes
