// A ResolvedScene's surfaces and lights as an ANARI world on `device`:
// one Group per (geometry, shader) and one Instance per placement.
#pragma once

#include "GeometryBuilder.h"
#include "ResolvedScene.h"

#include <anari/anari.h>

namespace prism::nsi {

struct AnariWorld
{
  ANARIWorld world{nullptr};
  // Ambient light, which ANARI puts on the renderer rather than the world.
  std::array<float, 3> ambientColor{1, 1, 1};
  float ambientRadiance{0};
  // What camera rays that miss see: a uniform environment visible to the
  // camera shows as its colour; else black.
  std::array<float, 4> background{0, 0, 0, 1};
};

AnariWorld buildAnariWorld(ANARIDevice device,
    const ResolvedScene &scene,
    const ReportFunction &report);

} // namespace prism::nsi
