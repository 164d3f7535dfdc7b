// The denoiser filters irradiance, not color: dividing the albedo out
// before filtering and multiplying it back after keeps textures sharp.
#pragma once

#include "../math/Vec.h"
#include "DenoiseInputs.h"

#include <cstddef>

namespace prism::denoising {

// Clamp before dividing, so black texels don't become huge irradiance.
inline constexpr float kMinAlbedo = 0.01f;

// What pixel i's color is divided by before filtering and multiplied by
// after: its albedo clamped to kMinAlbedo, 1 per non-finite channel and
// without an albedo buffer.
float3 demodulationFactor(const float3 *albedo, size_t i);

// in.color over the factor, w = 0; non-finite colors become 0, not spread.
void demodulate(const DenoiseInputs &in, float4 *demodulated);

// filtered times the factor, alpha from in.color; reading before writing
// allows out == in.color.
void remodulate(const DenoiseInputs &in, const float4 *filtered, float4 *out);

} // namespace prism::denoising
