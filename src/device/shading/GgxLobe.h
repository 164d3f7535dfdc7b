// The base layer's GGX lobe, isotropic or anisotropic
// (KHR_materials_anisotropy): its D, G1, G2 and visible-normal sampling in
// the local shading frame, whatever the lobe's orientation. Isotropic lobes
// take exactly the isotropic functions' arithmetic, so a strength of 0
// renders bit for bit as without anisotropy.
#pragma once

#include "Microfacet.h"
#include "Sampling.h"

#include <cmath>

namespace prism {

class GgxLobe
{
 public:
  GgxLobe() = default;
  // roughness and strength in [0, 1]; `direction` (local frame, z ignored)
  // is where the lobe is widest: glTF's alpha_t = mix(alpha, 1, strength^2)
  // along it, alpha_b = alpha across. A strength of 0 or a direction of
  // zero length gives the isotropic lobe of width roughness^2.
  GgxLobe(float roughness, float strength, float2 direction);

  bool anisotropic() const
  {
    return m_anisotropic;
  }
  // The isotropic width (roughness^2).
  float alpha() const
  {
    return m_alpha;
  }
  float alphaAlong() const
  {
    return m_alphaX;
  }
  float alphaAcross() const
  {
    return m_alphaY;
  }
  // The roughness of the isotropic lobe whose albedo tables stand in for
  // this lobe's (energy compensation and layering): the geometric mean of
  // the two widths (the unit tests' white furnace bounds the error), the
  // roughness itself when isotropic.
  float albedoRoughness() const
  {
    return m_anisotropic ? std::sqrt(std::sqrt(m_alphaX * m_alphaY))
                         : m_roughness;
  }

  float D(float3 h) const
  {
    return m_anisotropic ? ggxD(toLobe(h), m_alphaX, m_alphaY)
                         : ggxD(h, m_alpha);
  }
  float G1(float3 w) const
  {
    return 1.f / (1.f + lambda(w));
  }
  float G2(float3 wo, float3 wi) const
  {
    return 1.f / (1.f + lambda(wo) + lambda(wi));
  }
  // A microfacet normal visible from wo (wo.z > 0), with density
  // G1(wo) max(0, wo.h) D(h) / wo.z.
  float3 sampleVisibleNormal(float3 wo, float2 u) const
  {
    if (!m_anisotropic)
      return sampleGgxVisibleNormal(wo, m_alpha, m_alpha, u);
    return fromLobe(sampleGgxVisibleNormal(toLobe(wo), m_alphaX, m_alphaY, u));
  }

 private:
  float lambda(float3 w) const
  {
    return m_anisotropic ? ggxLambda(toLobe(w), m_alphaX, m_alphaY)
                         : ggxLambda(w, m_alpha);
  }
  // Our frame to the lobe's (x along the direction) and back: a turn about
  // z.
  float3 toLobe(float3 w) const
  {
    return {w.x * m_cos + w.y * m_sin, w.y * m_cos - w.x * m_sin, w.z};
  }
  float3 fromLobe(float3 w) const
  {
    return {w.x * m_cos - w.y * m_sin, w.x * m_sin + w.y * m_cos, w.z};
  }

  bool m_anisotropic{false};
  float m_alpha{1.f};
  float m_alphaX{1.f}, m_alphaY{1.f};
  float m_cos{1.f}, m_sin{0.f};
  float m_roughness{1.f};
};

inline GgxLobe::GgxLobe(float roughness, float strength, float2 direction)
    : m_alpha(roughness * roughness),
      m_alphaX(m_alpha),
      m_alphaY(m_alpha),
      m_roughness(roughness)
{
  const float length =
      std::sqrt(direction.x * direction.x + direction.y * direction.y);
  if (!(strength > 0.f) || !(length > 1e-6f) || !std::isfinite(length))
    return;
  // Below this width the narrow axis would be a mirror that float half
  // vectors cannot resolve (as Bsdf's delta threshold, made ten times
  // wider because the other axis is not a mirror).
  constexpr float kNarrowest = 1e-3f;
  m_anisotropic = true;
  m_cos = direction.x / length;
  m_sin = direction.y / length;
  m_alphaY = max(m_alpha, kNarrowest);
  m_alphaX = max(m_alphaY, lerp(m_alpha, 1.f, strength * strength));
}

} // namespace prism
