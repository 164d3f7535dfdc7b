#include "NormalMapping.h"

#include "../material/Material.h"
#include "../shading/Sampling.h"

namespace prism {

bool tangentFrame(const SurfaceHit &surface,
    const rt::Hit &hit,
    const float3 &normal,
    float3 &tangent,
    float3 &bitangent)
{
  float4 objectTangent;
  if (!surface.surface->geometry()->tangentAt(hit, objectTangent)) {
    orthonormalBasis(normal, tangent, bitangent);
    return true;
  }
  const float3 t{objectTangent.x, objectTangent.y, objectTangent.z};
  tangent = surface.placement->identity()
                ? t
                : transformDirection(surface.placement->worldFromObject(), t);
  tangent = tangent - normal * dot(normal, tangent);
  if (!(lengthSquared(tangent) > 1e-20f))
    return false;
  tangent = normalize(tangent);
  bitangent = cross(normal, tangent) * objectTangent.w;
  return true;
}

float3 normalMapped(const SurfaceHit &surface,
    const rt::Hit &hit,
    const float3 &normal,
    const float3 &mapped,
    const float3 &towardsViewer)
{
  float3 tangent, bitangent;
  if (!tangentFrame(surface, hit, normal, tangent, bitangent))
    return normal;
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
  const MaterialShading shading = surface.material().shade(surface.attributes);
  if (!shading.hasNormalMap)
    return surface.shadingNormal;
  return normalMapped(
      surface, hit, surface.shadingNormal, shading.normalMap, towardsViewer);
}

} // namespace prism
