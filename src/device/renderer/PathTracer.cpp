#include "PathTracer.h"

#include "../light/PlacedLight.h"
#include "../material/Matte.h"
#include "../material/PhysicallyBased.h"
#include "../shading/Bsdf.h"
#include "SampleHash.h"

#include <algorithm>
#include <cmath>

namespace prism {
namespace {

// Random streams per bounce: direction, lobe, light choice, light point,
// opacity.
constexpr uint32_t kStreamsPerBounce = 5;

float2 random2(uint32_t x, uint32_t y, uint32_t sample, uint32_t stream)
{
  return hashedSample2D(x, y, sample, 16 + stream);
}

float powerHeuristic(float a, float b)
{
  const float a2 = a * a, b2 = b * b;
  return a2 + b2 > 0.f ? a2 / (a2 + b2) : 0.f;
}

float maxComponent(const float3 &v)
{
  return std::max(v.x, std::max(v.y, v.z));
}

// An orthonormal frame around n (Duff et al. 2017).
void frameAround(const float3 &n, float3 &t, float3 &b)
{
  const float sign = std::copysign(1.f, n.z);
  const float a = -1.f / (sign + n.z);
  const float c = n.x * n.y * a;
  t = {1.f + sign * n.x * n.x * a, sign * c, -sign * n.x};
  b = {c, sign + n.y * n.y * a, -n.y};
}

// The material at a hit as BSDF inputs, and what the BSDF does not cover.
struct ShadingInputs
{
  BsdfInputs bsdf;
  float opacity{1.f};
  float3 emissive{0.f, 0.f, 0.f};
};

ShadingInputs shadingInputs(const SurfaceHit &hit)
{
  ShadingInputs out;
  const Material &material = hit.material();
  if (auto *pbr = dynamic_cast<const PhysicallyBased *>(&material)) {
    const PhysicallyBased::Values values = pbr->evaluate(hit.attributes);
    out.bsdf = physicallyBasedBsdfInputs(values);
    out.emissive = values.emissive;
  } else {
    const float4 base = material.baseColorAndOpacity(hit.attributes);
    out.bsdf = matteBsdfInputs(float3{base.x, base.y, base.z});
  }
  out.opacity =
      material.coverage(material.baseColorAndOpacity(hit.attributes).w);
  return out;
}

} // namespace

void PathTracer::commitParameters()
{
  Renderer::commitParameters();
  m_maxPathLength =
      std::clamp(read<int32_t>("maxPathLength", ANARI_INT32, 8), 1, 1024);
  m_ambient = m_ambientColor * std::max(m_ambientRadiance, 0.f);
}

float3 PathTracer::lightsAlong(const RenderContext &context,
    const float3 &origin,
    const float3 &direction,
    float hitDistance,
    float bsdfPdf,
    bool bsdfWasDelta,
    bool cameraRay) const
{
  const auto &lights = context.world->lights();
  const float pickProbability =
      lights.empty() ? 0.f : 1.f / float(lights.size());
  float3 sum{0.f, 0.f, 0.f};
  for (const auto &light : lights) {
    if (light->isDelta() || (cameraRay && !light->visibleToCamera))
      continue;
    float distance = 0.f, lightPdf = 0.f;
    const float3 radiance =
        light->radianceAlong(origin, direction, distance, lightPdf);
    if (distance >= hitDistance || maxComponent(radiance) <= 0.f)
      continue;
    // Camera rays and delta bounces could not have sampled the light.
    const float weight =
        cameraRay || bsdfWasDelta
            ? 1.f
            : powerHeuristic(bsdfPdf, lightPdf * pickProbability);
    sum = sum + radiance * weight;
  }
  return sum;
}

PixelSample PathTracer::shadeSample(const RenderContext &context,
    const Ray &primaryRay,
    const rt::Hit &primaryHit,
    uint32_t x,
    uint32_t y) const
{
  Ray ray = primaryRay;
  rt::Hit hit = primaryHit;
  PixelSample sample;
  const uint32_t n = context.sampleIndex;
  const auto &lights = context.world->lights();
  float3 radiance{0.f, 0.f, 0.f};
  float3 throughput{1.f, 1.f, 1.f};
  float previousPdf = 0.f;
  bool previousDelta = true;
  bool first = true;
  int bounce = 0;
  for (int step = 0; step < 4 * m_maxPathLength + 64; step++) {
    const bool cameraRay = bounce == 0;
    SurfaceHit surface;
    const bool found = hit.found()
                       && resolveSurfaceHit(
                           *context.world, ray, hit, surface, HitDetail::Full);
    const float hitDistance = found ? hit.t : ray.tMax;
    radiance = radiance
               + throughput
                     * lightsAlong(context,
                         ray.origin,
                         ray.direction,
                         hitDistance,
                         previousPdf,
                         previousDelta,
                         cameraRay);
    if (!found) {
      if (cameraRay) {
        const float4 bg = background(x, y, context.width, context.height);
        sample.color = float4{
            radiance.x + bg.x, radiance.y + bg.y, radiance.z + bg.z, bg.w};
        return sample;
      }
      radiance = radiance + throughput * m_ambient;
      break;
    }

    const ShadingInputs inputs = shadingInputs(surface);
    const uint32_t stream = uint32_t(bounce) * kStreamsPerBounce;
    // See-through surfaces: pass through with probability 1 - opacity.
    if (inputs.opacity < 1.f
        && random2(x, y, n, stream + 4).x >= inputs.opacity) {
      ray.tMin = hit.t + std::max(1e-4f, hit.t * 1e-5f);
      context.world->intersect(
          ray.origin, ray.direction, ray.tMin, ray.tMax, hit, ray.time);
      continue;
    }
    if (first) {
      sample.depth = hit.t;
      sample.normal = surface.shadingNormal;
      sample.albedo = inputs.bsdf.baseColor;
      sample.primitiveId = surface.attributes.primitiveId;
      sample.objectId = surface.surface->id();
      sample.instanceId = surface.placement->instanceId;
      first = false;
    }
    radiance = radiance + throughput * inputs.emissive;
    if (bounce + 1 >= m_maxPathLength)
      break;

    // The local shading frame around the geometry's own (unflipped)
    // shading normal: the BSDF needs to know which side the viewer is on to
    // tell entering a medium from leaving it.
    float3 tangent, bitangent;
    const float3 normal = surface.backFacing ? surface.shadingNormal * -1.f
                                             : surface.shadingNormal;
    frameAround(normal, tangent, bitangent);
    auto toLocal = [&](const float3 &v) {
      return float3{dot(v, tangent), dot(v, bitangent), dot(v, normal)};
    };
    auto toWorld = [&](const float3 &v) {
      return tangent * v.x + bitangent * v.y + normal * v.z;
    };
    const Bsdf bsdf(inputs.bsdf);
    const float3 wo = toLocal(ray.direction * -1.f);
    const float offset = 1e-4f * std::max(1.f, hit.t);

    // Next-event estimation: one light, chosen uniformly.
    if (!lights.empty() && bsdf.hasNonDeltaLobes()) {
      const float2 pick = random2(x, y, n, stream + 2);
      const size_t index =
          std::min(size_t(pick.x * float(lights.size())), lights.size() - 1);
      const PlacedLight &light = *lights[index];
      const LightSample ls =
          light.sample(surface.position, random2(x, y, n, stream + 3));
      const float3 wi = toLocal(ls.direction);
      if (ls.pdf > 0.f && maxComponent(ls.radiance) > 0.f) {
        const float3 f = bsdf.eval(wo, wi);
        if (maxComponent(f) > 0.f) {
          const float3 side = dot(ls.direction, surface.geometricNormal) > 0.f
                                  ? surface.geometricNormal
                                  : surface.geometricNormal * -1.f;
          const float3 origin = surface.position + side * offset;
          rt::Hit blocker;
          const float tMax = std::isinf(ls.distance)
                                 ? ls.distance
                                 : ls.distance * (1.f - 1e-4f) - offset;
          if (!context.world->intersect(
                  origin, ls.direction, 0.f, tMax, blocker, ray.time)) {
            const float pickPdf = ls.pdf / float(lights.size());
            const float weight =
                ls.delta ? 1.f : powerHeuristic(pickPdf, bsdf.pdf(wo, wi));
            radiance = radiance
                       + throughput * f * ls.radiance
                             * (std::abs(wi.z) * weight / pickPdf);
          }
        }
      }
    }

    // Continue the path by sampling the BSDF.
    const float2 direction = random2(x, y, n, stream);
    const float lobe = random2(x, y, n, stream + 1).x;
    const BsdfSample bs = bsdf.sample(wo, direction, lobe);
    if (!bs.valid())
      break;
    throughput = throughput * bs.weight;
    previousPdf = bs.pdf;
    previousDelta = bs.isDelta();
    const float3 wiWorld = normalize(toWorld(bs.wi));
    const float3 side = dot(wiWorld, surface.geometricNormal) > 0.f
                            ? surface.geometricNormal
                            : surface.geometricNormal * -1.f;
    ray = Ray{surface.position + side * offset,
        wiWorld,
        0.f,
        std::numeric_limits<float>::infinity(),
        primaryRay.time};
    bounce++;
    // Russian roulette after three bounces keeps long paths unbiased.
    if (bounce > 3) {
      const float survive = std::min(0.95f, maxComponent(throughput));
      if (random2(x, y, n, stream + 4).y >= survive)
        break;
      throughput = throughput / survive;
    }
    context.world->intersect(
        ray.origin, ray.direction, ray.tMin, ray.tMax, hit, ray.time);
  }
  sample.color = float4{radiance.x, radiance.y, radiance.z, 1.f};
  return sample;
}

} // namespace prism
