#include "AmbientOcclusion.h"

#include "SampleHash.h"

#include <algorithm>
#include <cmath>

namespace prism {
namespace {

// A cosine-distributed direction around `n` (Malley's method).
float3 cosineDirection(const float3 &n, float2 u)
{
  const float radius = std::sqrt(u.x);
  const float phi = 2.f * float(M_PI) * u.y;
  const float3 helper =
      std::abs(n.x) > 0.9f ? float3{0, 1, 0} : float3{1, 0, 0};
  const float3 t = normalize(cross(helper, n));
  const float3 b = cross(n, t);
  const float z = std::sqrt(std::max(0.f, 1.f - u.x));
  return t * (radius * std::cos(phi)) + b * (radius * std::sin(phi)) + n * z;
}

} // namespace

void AmbientOcclusion::commitParameters()
{
  Renderer::commitParameters();
  const int32_t samples = read<int32_t>("aoSamples", ANARI_INT32, 1);
  m_samples = uint32_t(std::clamp(samples, 1, 1024));
  m_distance = read<float>("aoDistance", ANARI_FLOAT32, 1e20f);
  if (!(m_distance > 0.f)) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'aoDistance' must be positive; using 1e20");
    m_distance = 1e20f;
  }
}

PixelSample AmbientOcclusion::shadeSample(const RenderContext &context,
    const Ray &ray,
    const rt::Hit &hit,
    uint32_t x,
    uint32_t y) const
{
  PixelSample sample;
  SurfaceHit surface;
  if (!resolveSurfaceHit(
          *context.world, ray, hit, surface, HitDetail::ForMaterial)) {
    sample.color = background(x, y, context.width, context.height);
    return sample;
  }
  const float4 base =
      surface.material().baseColorAndOpacity(surface.attributes);
  // Offset along the geometric normal, scaled with the distance, so the
  // occlusion rays do not hit the surface they start on.
  const float3 origin =
      surface.position
      + surface.geometricNormal * (1e-4f * std::max(1.f, hit.t));
  uint32_t open = 0;
  for (uint32_t i = 0; i < m_samples; i++) {
    const float2 u =
        hashedSample2D(x, y, context.sampleIndex * m_samples + i, 2);
    const float3 direction = cosineDirection(surface.shadingNormal, u);
    rt::Hit blocker;
    open += context.world->intersect(
                origin, direction, 0.f, m_distance, blocker, ray.time)
                ? 0u
                : 1u;
  }
  const float visibility = float(open) / float(m_samples);
  sample.color = float4{
      base.x * visibility, base.y * visibility, base.z * visibility, 1.f};
  sample.depth = hit.t;
  sample.normal = surface.shadingNormal;
  sample.albedo = float3{base.x, base.y, base.z};
  sample.primitiveId = surface.attributes.primitiveId;
  sample.objectId = surface.surface->id();
  sample.instanceId = surface.placement->instanceId;
  return sample;
}

} // namespace prism
