#include "NormalMapping.h"

#include "../material/PhysicallyBased.h"
#include "../shading/Sampling.h"

namespace prism {

float3 normalMapped(const SurfaceHit &surface,
    const rt::Hit &hit,
    const float3 &normal,
    const float3 &mapped,
    const float3 &towardsViewer)
{
  float4 objectTangent;
  float3 tangent, bitangent;
  if (surface.surface->geometry()->tangentAt(hit, objectTangent)) {
    const float3 t{objectTangent.x, objectTangent.y, objectTangent.z};
    tangent = surface.placement->identity
                  ? t
                  : transformDirection(surface.placement->worldFromObject, t);
    tangent = tangent - normal * dot(normal, tangent);
    if (!(lengthSquared(tangent) > 1e-20f))
      return normal;
    tangent = normalize(tangent);
    bitangent = cross(normal, tangent) * objectTangent.w;
  } else {
    orthonormalBasis(normal, tangent, bitangent);
  }
  const float3 bent =
      tangent * mapped.x + bitangent * mapped.y + normal * mapped.z;
  if (!(lengthSquared(bent) > 1e-20f))
    return normal;
  const float3 result = normalize(bent);
  const bool sameSide =
      (dot(result, towardsViewer) > 0.f) == (dot(normal, towardsViewer) > 0.f);
  return sameSide ? result : normal;
}

float3 shadingNormalWithMap(
    const SurfaceHit &surface, const rt::Hit &hit, const float3 &towardsViewer)
{
  const PhysicallyBased *pbr = surface.material().asPhysicallyBased();
  if (!pbr
      || pbr->inputs().normal.source()
             == MaterialInput<float3>::Source::Constant)
    return surface.shadingNormal;
  const PhysicallyBased::Values values = pbr->evaluate(surface.attributes);
  return normalMapped(
      surface, hit, surface.shadingNormal, values.normal, towardsViewer);
}

} // namespace prism
