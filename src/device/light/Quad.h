// The quad light (KHR_LIGHT_QUAD): a parallelogram at `position` spanned by
// edge1 and edge2, emitting from its front (edge2 x edge1), back or both
// sides. Without intensityDistribution it is Lambertian: uniform radiance,
// `intensity` (W/sr) being the intensity along the normal. With one, the
// table scales `intensity` per direction in the C-gamma system around the
// front normal, C0 along edge1 (spec 5.7.4).
#pragma once

#include "Light.h"

namespace prism::light {

class Quad : public Light
{
 public:
  enum class Side { kFront, kBack, kBoth };

  explicit Quad(DeviceState &device);

  void finalize() override;
  std::unique_ptr<PlacedLight> place(
      const mat3x4 &worldFromObject) const override;

 protected:
  void commitParameters() override;

 private:
  float3 m_position{0.f, 0.f, 0.f};
  float3 m_edge1{1.f, 0.f, 0.f};
  float3 m_edge2{0.f, 1.f, 0.f};
  Side m_side{Side::kFront};
  Brightness m_brightness;
  Array *m_distributionArray{nullptr}; // until finalize(), see Light.h
  std::shared_ptr<const IntensityDistribution> m_distribution;
  // Integral over the sphere of the intensity per unit `intensity` (sr).
  double m_emissionIntegral{0.0};
};

} // namespace prism::light
