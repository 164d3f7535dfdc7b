#include "AmbientOcclusion.h"

#include "../math/LocalFrame.h"
#include "../math/SphereSampling.h"
#include "SampleHash.h"
#include "SampleSequence.h"
#include "VolumeTracing.h"
#include "wavefront/RayTransport.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace prism {
namespace {

// Surfaces seen through at most this many see-through layers per pixel.
constexpr uint16_t kMaxLayers = 64;

} // namespace

void AmbientOcclusion::commitParameters()
{
  Renderer::commitParameters();
  m_samples = uint32_t(param<int32_t>("aoSamples"));
  // 0 is accepted: no occlusion ray reaches beyond its own start, so
  // nothing occludes and the image is the base color.
  m_distance = param<float>("aoDistance");
  m_seed = uint32_t(param<int32_t>("seed"));
}

void AmbientOcclusion::renderTile(const RenderContext &context,
    const Tile &tile,
    FrameBuffers &buffers,
    const std::atomic<bool> &cancel) const
{
  const RayTransport &transport = *context.transport;
  const uint32_t width = tile.x1 - tile.x0;
  const size_t count = size_t(width) * (tile.y1 - tile.y0);
  const auto workspace = m_workspaces.take();
  std::vector<PixelSample> &samples = workspace->samples;
  std::vector<float> &times = workspace->times;
  std::vector<float> &open = workspace->open;
  std::vector<uint16_t> &layers = workspace->layers;
  rt::RayQueue &rays = workspace->rays, &next = workspace->next,
               &occlusion = workspace->occlusion;
  samples.assign(count, PixelSample{});
  times.assign(count, 0.5f);
  open.assign(count, 0.f);
  layers.assign(count, 0);
  rays.clear();
  occlusion.clear();
  auto pixelOf = [&](size_t i) {
    return uint2{tile.x0 + uint32_t(i % width), tile.y0 + uint32_t(i / width)};
  };
  for (size_t i = 0; i < count; i++) {
    const uint2 pixel = pixelOf(i);
    const Ray ray = cameraRay(context, pixel.x, pixel.y);
    times[i] = ray.time;
    rays.push(
        ray.origin, ray.direction, ray.tMin, ray.tMax, ray.time, uint32_t(i));
    samples[i].color = background(context, pixel.x, pixel.y);
  }
  rays.setCoherent(true);
  // Camera rays, then their continuations through see-through surfaces.
  while (!rays.empty() && !cancel) {
    transport.traceClosest(rays, nullptr);
    next.clear();
    for (size_t r = 0; r < rays.size(); r++) {
      const uint32_t i = rays.tag(r);
      const uint2 pixel = pixelOf(i);
      const rt::Hit hit = rays.hit(r);
      const Ray ray{rays.origin(r),
          rays.direction(r),
          rays.tMin(r),
          std::numeric_limits<float>::infinity(),
          times[i]};
      if (rays.untraceable(r))
        continue; // the background stays
      // A volume before the hit absorbs the ray with the probability it
      // absorbs light (delta tracking): frames accumulate its emission.
      if (!context.world->volumes().empty()) {
        HashedStream random(
            sequenceSeed(pixel.x, pixel.y, 40 + layers[i], context.seed)
            ^ mixBits(context.sampleIndex));
        VolumeCollision collision;
        if (trackCollision(*context.world,
                ray.origin,
                ray.direction,
                ray.tMin,
                hit.found() ? hit.t : ray.tMax,
                random,
                collision)) {
          PixelSample &sample = samples[i];
          sample.color = float4{
              collision.color.x, collision.color.y, collision.color.z, 1.f};
          sample.depth = collision.t;
          sample.albedo = collision.color;
          sample.objectId = collision.objectId;
          sample.instanceId = collision.instanceId;
          // Emission is not occluded: every (unsent) ray counts as open.
          open[i] = float(m_samples);
          continue;
        }
      }
      SurfaceHit surface;
      if (!resolveSurfaceHit(
              *context.world, ray, hit, surface, HitDetail::ForMaterial))
        continue; // the background stays
      const float4 base =
          surface.material().baseColorAndOpacity(surface.attributes);
      const float coverage = surface.material().coverage(base.w);
      if (coverage < 1.f
          && sobolSample2D(context.sampleIndex,
                 sequenceSeed(pixel.x, pixel.y, 4 + layers[i], context.seed))
                     .x
                 >= coverage) {
        if (++layers[i] < kMaxLayers) {
          next.push(ray.origin,
              ray.direction,
              hit.t + std::max(1e-4f, hit.t * 1e-5f),
              std::numeric_limits<float>::infinity(),
              ray.time,
              i);
        }
        continue;
      }
      PixelSample &sample = samples[i];
      sample.color = float4{base.x, base.y, base.z, 1.f};
      sample.depth = hit.t;
      sample.normal = surface.shadingNormal;
      sample.albedo = float3{base.x, base.y, base.z};
      sample.primitiveId = surface.attributes.primitiveId;
      sample.objectId = surface.surface->id();
      sample.instanceId = surface.placement->instanceId;
      // Offset along the geometric normal, scaled with the distance, so
      // the occlusion rays do not hit the surface they start on.
      const float3 origin =
          surface.position
          + surface.geometricNormal * (1e-4f * std::max(1.f, hit.t));
      // Cosine-distributed directions around the shading normal.
      const LocalFrame hemisphere = LocalFrame::around(surface.shadingNormal);
      for (uint32_t k = 0; k < m_samples; k++) {
        const float2 u = sobolSample2D(context.sampleIndex * m_samples + k,
            sequenceSeed(pixel.x, pixel.y, 2, context.seed));
        occlusion.push(origin,
            hemisphere.toWorld(sampleCosineHemisphere(u)),
            0.f,
            m_distance,
            ray.time,
            i);
      }
    }
    std::swap(rays, next);
  }
  if (cancel)
    return;
  transport.traceOcclusion(occlusion);
  for (size_t k = 0; k < occlusion.size(); k++)
    open[occlusion.tag(k)] += occlusion.transmittance(k).x;
  for (size_t i = 0; i < count; i++) {
    PixelSample &sample = samples[i];
    if (std::isfinite(sample.depth)) {
      const float visibility = open[i] / float(m_samples);
      sample.color = float4{sample.color.x * visibility,
          sample.color.y * visibility,
          sample.color.z * visibility,
          1.f};
    }
    const uint2 pixel = pixelOf(i);
    store(context, buffers, pixel.x, pixel.y, sample);
  }
}

} // namespace prism
