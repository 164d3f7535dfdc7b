#include "SurfaceHit.h"

namespace prism {

bool resolveSurfaceHit(const World &world,
    const Ray &ray,
    const rt::Hit &hit,
    SurfaceHit &out,
    HitDetail detail)
{
  if (!hit.found())
    return false;
  const World::Placement &placement = world.placement(hit.instanceId);
  const Surface *surface = placement.group()->surface(hit.geometryId);
  if (!surface)
    return false;
  out.surface = surface;
  out.placement = &placement;
  out.distance = hit.t;
  out.position = ray.origin + ray.direction * hit.t;
  const Material &material = *surface->material();
  const bool interpolate =
      detail == HitDetail::Full
      || (detail == HitDetail::ForMaterial && material.colorReadsAttributes())
      || (detail == HitDetail::ForShading && material.readsAttributes());
  if (interpolate) {
    out.attributes = AttributeValues{};
    if (const Instance *instance = placement.instance())
      instance->applyAttributes(out.attributes);
  }
  // Where a moving instance was when the ray passed.
  const mat3x4 objectFromWorld = placement.identity()
                                     ? kIdentityMat3x4
                                     : placement.objectFromWorldAt(ray.time);
  const float3 objectPosition =
      placement.identity() ? out.position
                           : transformPoint(objectFromWorld, out.position);
  const float3 objectNormal = surface->geometry()->attributesAt(
      hit, objectPosition, out.attributes, interpolate, ray.time);
  float3 geometric = placement.identity() ? hit.geometricNormal
                                          : transformNormal(objectFromWorld,
                                              hit.geometricNormal);
  geometric = normalize(geometric);
  // The geometry returns its shading normal normalised already.
  float3 shading =
      placement.identity()
          ? objectNormal
          : normalize(transformNormal(objectFromWorld, objectNormal));
  out.backFacing = dot(geometric, ray.direction) > 0.f;
  if (out.backFacing)
    geometric = geometric * -1.f;
  if (dot(shading, geometric) < 0.f)
    shading = shading * -1.f;
  out.geometricNormal = geometric;
  out.shadingNormal = shading;
  out.attributes[Attribute::WorldPosition] =
      float4{out.position.x, out.position.y, out.position.z, 1.f};
  out.attributes[Attribute::WorldNormal] =
      float4{shading.x, shading.y, shading.z, 0.f};
  return true;
}

void recordSurfaceChannels(PixelSample &sample,
    float t,
    const SurfaceHit &surface,
    const float3 &albedo)
{
  sample.depth = t;
  sample.normal = surface.shadingNormal;
  sample.albedo = albedo;
  sample.primitiveId = surface.attributes.primitiveId;
  sample.objectId = surface.surface->id();
  sample.instanceId = surface.placement->instanceId();
}

} // namespace prism
