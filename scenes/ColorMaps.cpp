#include "ColorMaps.h"

#include <cmath>

namespace prism::scenes {
namespace {

Vec3 fromHex(unsigned rgb)
{
  return {float((rgb >> 16) & 0xff) / 255.f,
      float((rgb >> 8) & 0xff) / 255.f,
      float(rgb & 0xff) / 255.f};
}

float srgbToLinear(float c)
{
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

} // namespace

const std::vector<ColorMap> &colorMaps()
{
  static const std::vector<ColorMap> maps = {
      // Moreland's diverging cool-to-warm map.
      {"coolwarm",
          {{0.23f, 0.30f, 0.75f},
              {0.55f, 0.69f, 1.f},
              {0.87f, 0.87f, 0.87f},
              {0.96f, 0.6f, 0.48f},
              {0.71f, 0.02f, 0.15f}}},
      // van der Walt and Smith's perceptually uniform maps, at ninths.
      {"viridis",
          {fromHex(0x440154),
              fromHex(0x472d7b),
              fromHex(0x3b528b),
              fromHex(0x2c728e),
              fromHex(0x21918c),
              fromHex(0x28ae80),
              fromHex(0x5ec962),
              fromHex(0xaddc30),
              fromHex(0xfde725)}},
      {"inferno",
          {fromHex(0x000004),
              fromHex(0x1f0c48),
              fromHex(0x550f6d),
              fromHex(0x88226a),
              fromHex(0xba3655),
              fromHex(0xe35933),
              fromHex(0xf98c0a),
              fromHex(0xf9c932),
              fromHex(0xfcffa4)}},
      {"grayscale", {{0.f, 0.f, 0.f}, {1.f, 1.f, 1.f}}},
  };
  return maps;
}

const ColorMap *findColorMap(const std::string &name)
{
  for (const ColorMap &map : colorMaps())
    if (name == map.name)
      return &map;
  return nullptr;
}

std::string colorMapNames()
{
  std::string names;
  for (const ColorMap &map : colorMaps())
    names += std::string(names.empty() ? "" : ", ") + map.name;
  return names;
}

std::vector<Vec3> linearColors(const ColorMap &map)
{
  std::vector<Vec3> colors = map.srgbControlPoints;
  for (Vec3 &color : colors)
    for (float &c : color)
      c = srgbToLinear(c);
  return colors;
}

} // namespace prism::scenes
