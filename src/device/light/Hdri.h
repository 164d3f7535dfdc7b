// The hdri light (KHR_LIGHT_HDRI): an equirectangular radiance image
// (W/sr/m^2) around the scene at infinity. Column s of the image runs
// around `up` with the image's center column towards `direction` and s
// increasing to the right of a viewer looking that way; row t runs from
// `up` (first row) to -up (last row). Radiance is filtered bilinearly
// between texel centres (wrapping around `up`, held at the poles), so a
// small image seen behind the scene is smooth, not blocky. Importance
// sampling picks a texel in proportion to the filtered luminance's average
// over it times its solid angle, then a point in it in proportion to the
// filtered luminance itself (a quarter of the texel, then the bilinear
// patch that quarter lies in): the density follows the radiance within a
// texel too, so a sun of a few texels is sampled as sharply as it is lit.
// A receiver facing one way samples towards its side (HdriHemispheres).
#pragma once

#include "Distribution2D.h"
#include "HdriHemispheres.h"
#include "Light.h"

#include <cstdint>

namespace prism::light {

// The decoded image and its sampling density, shared by every placement.
struct HdriImage
{
  std::vector<float3> texels; // (i, j) at i + j * width, scale applied
  size_t width{0}, height{0};
  Distribution2D distribution;           // of luminance x solid angle per texel
  HdriHemispheres hemispheres;           // the same, towards one side
  std::vector<float> texelSolidAngle;    // per row
  float3 averageRadiance{0.f, 0.f, 0.f}; // over the sphere of directions

  // Texel (i, j), i wrapping around and j held to the image.
  const float3 &texel(int64_t i, int64_t j) const;
  // The bilinear filter at image coordinates `st` in [0, 1]^2.
  float3 filtered(const float2 &st) const;
  // The filtered image's average over texel (i, j).
  float3 texelAverage(int64_t i, int64_t j) const;
  // A point of [0, 1)^2 in texel (i, j) for a uniform `u`, with density in
  // proportion to the filtered luminance (uniform where it is all 0).
  float2 sampleInTexel(int64_t i, int64_t j, float2 u) const;
  // The density over [0, 1)^2 of the points the distribution and
  // sampleInTexel choose, at `st` where the filtered radiance is
  // `radiance`: the texel's probability times the density in it is the
  // filtered luminance times the texel's solid angle over the mean weight.
  float density(const float2 &st, const float3 &radiance) const;
};

class Hdri : public Light
{
 public:
  explicit Hdri(DeviceState &device);

  void finalize() override;
  std::unique_ptr<PlacedLight> place(
      const mat3x4 &worldFromObject) const override;

 protected:
  void commitParameters() override;

 private:
  float3 m_up{0.f, 0.f, 1.f};        // unit
  float3 m_direction{1.f, 0.f, 0.f}; // unit
  float m_scale{1.f};
  Array *m_radianceArray{nullptr}; // until finalize(), see Light.h
  std::shared_ptr<const HdriImage> m_image;
};

} // namespace prism::light
