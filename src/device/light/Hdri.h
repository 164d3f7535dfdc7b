// The hdri light (KHR_LIGHT_HDRI): an equirectangular radiance image
// (W/sr/m^2) around the scene at infinity. Column s of the image runs
// around `up` with the image's center column towards `direction` and s
// increasing to the right of a viewer looking that way; row t runs from
// `up` (first row) to -up (last row). Importance sampled by a
// piecewise-constant density over the texels, proportional to luminance
// times solid angle; radiance is looked up nearest-texel, so the density
// and the radiance a renderer sees agree texel by texel.
#pragma once

#include "Distribution2D.h"
#include "Light.h"

namespace prism::light {

// The decoded image and its sampling density, shared by every placement.
struct HdriImage
{
  std::vector<float3> texels; // (i, j) at i + j * width, scale applied
  size_t width{0}, height{0};
  Distribution2D distribution;
  float3 averageRadiance{0.f, 0.f, 0.f}; // over the sphere of directions
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
