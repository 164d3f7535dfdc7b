// What the denoiser reads: a frame's color and its guide buffers.
#pragma once

#include "../math/Vec.h"

#include <cstdint>

namespace prism {

// A frame's linear buffers, row 0 at the bottom; NULL guides are ignored.
struct DenoiseInputs
{
  uint32_t width, height;
  const float4 *color;  // average of `samples` samples; alpha passes through
  const float3 *albedo; // average albedo, divided out so textures stay sharp
  const float3 *normal; // world space, average of unit normals; 0 = no hit
  const float *depth;   // distance to the camera, +inf where nothing was hit
  uint32_t samples;     // samples averaged into color (0 is treated as 1)
};

} // namespace prism
