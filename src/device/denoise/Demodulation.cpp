#include "Demodulation.h"

#include "PixelGrid.h"

#include <cmath>

namespace prism::denoising {

float3 demodulationFactor(const float3 *albedo, size_t i)
{
  if (!albedo)
    return {1.f, 1.f, 1.f};
  // A non-finite albedo would poison the round trip: skip that channel.
  const auto factor = [](float a) {
    return std::isfinite(a) ? max(a, kMinAlbedo) : 1.f;
  };
  const float3 a = albedo[i];
  return {factor(a.x), factor(a.y), factor(a.z)};
}

void demodulate(const DenoiseInputs &in, float4 *demodulated)
{
  const PixelGrid grid{int(in.width), int(in.height)};
  forEachRow(grid, [&](int y) {
    for (int x = 0; x < grid.width; x++) {
      const size_t i = grid.index(x, y);
      float3 color = xyz(in.color[i]);
      if (!(std::isfinite(color.x) && std::isfinite(color.y)
              && std::isfinite(color.z)))
        color = {0.f, 0.f, 0.f};
      demodulated[i] = makeVec4(color / demodulationFactor(in.albedo, i), 0.f);
    }
  });
}

void remodulate(const DenoiseInputs &in, const float4 *filtered, float4 *out)
{
  const PixelGrid grid{int(in.width), int(in.height)};
  forEachRow(grid, [&](int y) {
    for (int x = 0; x < grid.width; x++) {
      const size_t i = grid.index(x, y);
      const float alpha = in.color[i].w;
      out[i] =
          makeVec4(xyz(filtered[i]) * demodulationFactor(in.albedo, i), alpha);
    }
  });
}

} // namespace prism::denoising
