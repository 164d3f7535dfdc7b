// Brightness of a linear RGB color, where colors are compared or weighed:
// the denoiser's edge stops and noise, lights' selection and hdri density.
#pragma once

#include "Vec.h"

namespace prism {

// Rec. 709 luminance of linear RGB.
inline float luminance(float3 rgb)
{
  return 0.2126f * rgb.x + 0.7152f * rgb.y + 0.0722f * rgb.z;
}

} // namespace prism
