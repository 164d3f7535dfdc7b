#include "TransferFunctionEdit.h"

#include "ColorMaps.h"

#include <cmath>

namespace prism::viewer {

std::string transferFunctionOptions(
    const TransferFunctionEdit &edit, scene_io::TransferFunctionOptions &out)
{
  out = {};
  const auto &maps = scenes::colorMaps();
  if (edit.colorMap < 0 || size_t(edit.colorMap) >= maps.size())
    return "no color map " + std::to_string(edit.colorMap);
  if (edit.opacities.empty())
    return "the opacity curve needs a value";
  for (float o : edit.opacities)
    if (!(o >= 0.f && o <= 1.f))
      return "opacities are between 0 and 1";
  if (edit.customRange
      && !(std::isfinite(edit.range[0]) && std::isfinite(edit.range[1])
           && edit.range[0] < edit.range[1]))
    return "the value range needs low < high";
  if (!(edit.unitDistance > 0.f && std::isfinite(edit.unitDistance)))
    return "the unit distance must be above 0";
  out.colorMap = maps[edit.colorMap].name;
  out.opacities = edit.opacities;
  if (edit.customRange)
    out.valueRange = edit.range;
  out.unitDistance = edit.unitDistance;
  out.given = true;
  return {};
}

} // namespace prism::viewer
