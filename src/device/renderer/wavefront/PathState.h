// One path of a wavefront between bounces: what it carries so far and what
// it needs to weigh the next light it reaches (structure-of-arrays queues
// hold its rays; this holds everything else, indexed by the ray's tag).
#pragma once

#include "../../math/Vec.h"
#include "../FrameBuffers.h"
#include "MediumStack.h"

#include <cstdint>

namespace prism {

struct PathState
{
  float3 radiance{0.f, 0.f, 0.f};
  float3 throughput{1.f, 1.f, 1.f};
  // The pdf of the BSDF sample that started the current ray, and whether
  // it was a delta lobe (such rays weigh the light they reach fully).
  float previousPdf{0.f};
  // The receiver normal the light sample at that surface was chosen for
  // (PathTracer::receiverNormal), so hitting a light weighs it alike.
  float3 previousNormal{0.f, 0.f, 0.f};
  bool previousDelta{true};
  bool recordedFirstHit{false};
  // How much of the ambient light the last surface lets reach it (its
  // material's occlusion).
  float ambientVisibility{1.f};
  // The media the current ray travels through.
  MediumStack media;
  uint16_t bounce{0};      // scattering events so far (0: the camera ray)
  uint16_t layer{0};       // see-through surfaces passed at this bounce
  uint32_t x{0}, y{0};     // the pixel
  uint32_t seed{0};        // the pixel's (sequenceSeed() per decision)
  uint32_t sampleIndex{0}; // in the pixel's sample sequences
  float time{0.5f};        // within the shutter, shared by all its rays
  PixelSample sample;      // the first hit's channels and the final color
};

} // namespace prism
