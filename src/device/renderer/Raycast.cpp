#include "Raycast.h"

#include <algorithm>
#include <cmath>

namespace prism {
namespace {

// Surfaces seen through at most this many see-through layers per pixel.
constexpr int kMaxLayers = 64;

} // namespace

void Raycast::commitParameters()
{
  Renderer::commitParameters();
  m_eyeLightBlendRatio = std::clamp(
      read<float>("eyeLightBlendRatio", ANARI_FLOAT32, 0.5f), 0.f, 1.f);
}

PixelSample Raycast::shadeSample(const RenderContext &context,
    const Ray &ray,
    const rt::Hit &firstHit,
    uint32_t x,
    uint32_t y) const
{
  rt::Hit hit = firstHit;
  PixelSample sample;
  float3 color{0, 0, 0};
  float alpha = 0.f;
  bool first = true;
  for (int layer = 0; layer < kMaxLayers && hit.found(); layer++) {
    SurfaceHit surface;
    if (resolveSurfaceHit(
            *context.world, ray, hit, surface, HitDetail::ForMaterial)) {
      const float4 base =
          surface.material().baseColorAndOpacity(surface.attributes);
      const float coverage = surface.material().coverage(base.w);
      if (coverage > 0.f) {
        if (first) {
          sample.depth = hit.t;
          sample.normal = surface.shadingNormal;
          sample.albedo = float3{base.x, base.y, base.z};
          sample.primitiveId = surface.attributes.primitiveId;
          sample.objectId = surface.surface->id();
          sample.instanceId = surface.placement->instanceId;
          first = false;
        }
        const float cosine =
            std::abs(dot(surface.shadingNormal, ray.direction));
        const float light =
            m_eyeLightBlendRatio * cosine + (1.f - m_eyeLightBlendRatio);
        const float weight = (1.f - alpha) * coverage;
        color = color + float3{base.x, base.y, base.z} * (light * weight);
        alpha += weight;
        if (alpha >= 0.999f)
          break;
      }
    }
    hit = traceBeyond(*context.world, ray, hit);
  }
  const float4 background =
      this->background(x, y, context.width, context.height);
  const float rest = 1.f - alpha;
  sample.color = float4{color.x + rest * background.x,
      color.y + rest * background.y,
      color.z + rest * background.z,
      alpha + rest * background.w};
  return sample;
}

} // namespace prism
