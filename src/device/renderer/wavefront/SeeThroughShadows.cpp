#include "SeeThroughShadows.h"

#include "../SampleHash.h"
#include "../SurfaceHit.h"

#include <bit>

namespace prism {

bool SeeThroughShadows::at(const float3 &origin,
    const float3 &direction,
    float time,
    const rt::Hit &hit) const
{
  rt::Hit placed = hit;
  if (placed.instanceId == rt::kInvalidId)
    placed.instanceId = 0; // a group's scene traced directly: its placement
  if (placed.instanceId >= m_world.placementCount())
    return true;
  SurfaceHit surface;
  if (!resolveSurfaceHit(m_world,
          Ray{origin, direction, 0.f, hit.t, time},
          placed,
          surface,
          HitDetail::ForMaterial))
    return true;
  const Material &material = surface.material();
  const float coverage =
      material.coverage(material.baseColorAndOpacity(surface.attributes).w);
  if (!(coverage < 1.f))
    return true; // NaN too
  if (!(coverage > 0.f))
    return false;
  // The ray's own numbers and the hit's (its distance too: a ray leaves a
  // sphere or an isosurface's cell through the primitive it entered):
  // another ray, or the same ray at another crossing, decides anew; the
  // same ray at the same hit the same.
  uint32_t key = mixBits(hit.primitiveId ^ mixBits(hit.geometryId))
                 ^ hit.instanceId * 0x9e3779b9u;
  for (const float value : {hit.t,
           origin.x,
           origin.y,
           origin.z,
           direction.x,
           direction.y,
           direction.z})
    key = mixBits(key ^ std::bit_cast<uint32_t>(value));
  return float(key >> 8) * (1.f / 16777216.f) < coverage;
}

} // namespace prism
