#include "AmbientOcclusion.h"

#include "TileLoop.h"

#include "../math/LocalFrame.h"
#include "../math/SphereSampling.h"
#include "SampleHash.h"
#include "SampleSequence.h"
#include "VolumeTracing.h"
#include "wavefront/RayTransport.h"
#include "wavefront/WavefrontTile.h"

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

// A tile's wavefront: its camera rays (and their continuations through
// see-through surfaces) as one queue per bounce, all occlusion rays as
// one queue at the end.
class AmbientOcclusion::Wavefront final : public WavefrontTile<TileWorkspace>
{
 public:
  Wavefront(const AmbientOcclusion &renderer,
      const RenderContext &context,
      const Tile &tile,
      FrameBuffers &buffers);

  void packet(uint32_t x0, uint32_t y, int count) override;
  bool bounce() override;
  void finish() override;

 private:
  // Shades ray r of the bounce just traced: the first opaque surface's
  // color and its occlusion rays, a continuation through a see-through
  // layer, or a collision in a volume.
  void shadeRay(size_t r);
  // Whether pixel i's ray collides in a volume before `hitT` (delta
  // tracking), its sample then the volume's.
  bool collidesInVolume(uint32_t i, const Ray &ray, float hitT);

  const AmbientOcclusion &m_renderer;
  std::vector<PixelSample> &m_samples;
  std::vector<float> &m_times;
  std::vector<float> &m_open;
  std::vector<uint16_t> &m_layers;
  rt::RayQueue &m_rays, &m_next, &m_occlusion;
};

AmbientOcclusion::Wavefront::Wavefront(const AmbientOcclusion &renderer,
    const RenderContext &context,
    const Tile &tile,
    FrameBuffers &buffers)
    : WavefrontTile(context, tile, buffers, renderer.m_workspaces),
      m_renderer(renderer),
      m_samples(m_workspace->samples),
      m_times(m_workspace->times),
      m_open(m_workspace->open),
      m_layers(m_workspace->layers),
      m_rays(m_workspace->rays),
      m_next(m_workspace->next),
      m_occlusion(m_workspace->occlusion)
{
  m_samples.assign(m_count, PixelSample{});
  m_times.assign(m_count, 0.5f);
  m_open.assign(m_count, 0.f);
  m_layers.assign(m_count, 0);
  m_rays.clear();
  m_occlusion.clear();
}

void AmbientOcclusion::Wavefront::packet(uint32_t x0, uint32_t y, int count)
{
  for (int k = 0; k < count; k++) {
    const uint32_t x = x0 + uint32_t(k);
    const size_t i = indexOf(x, y);
    const Ray ray = m_context.cameraRay(x, y);
    m_times[i] = ray.time;
    m_rays.push(
        ray.origin, ray.direction, ray.tMin, ray.tMax, ray.time, uint32_t(i));
    m_samples[i].color = m_renderer.background(m_context, x, y);
  }
  m_rays.setCoherent(true);
}

bool AmbientOcclusion::Wavefront::bounce()
{
  if (m_rays.empty())
    return false;
  m_context.transport->traceClosest(m_rays, nullptr);
  m_next.clear();
  for (size_t r = 0; r < m_rays.size(); r++)
    shadeRay(r);
  std::swap(m_rays, m_next);
  return true;
}

bool AmbientOcclusion::Wavefront::collidesInVolume(
    uint32_t i, const Ray &ray, float hitT)
{
  const uint2 pixel = pixelOf(i);
  HashedStream random(
      sequenceSeed(pixel.x, pixel.y, 40 + m_layers[i], m_context.seed)
      ^ mixBits(m_context.sampleIndex));
  VolumeCollision collision;
  if (!trackCollision(*m_context.world,
          ray.origin,
          ray.direction,
          ray.tMin,
          hitT,
          random,
          collision))
    return false;
  PixelSample &sample = m_samples[i];
  sample.color =
      float4{collision.color.x, collision.color.y, collision.color.z, 1.f};
  sample.depth = collision.t;
  sample.albedo = collision.color;
  sample.objectId = collision.objectId;
  sample.instanceId = collision.instanceId;
  // Emission is not occluded: every (unsent) ray counts as open.
  m_open[i] = float(m_renderer.m_samples);
  return true;
}

void AmbientOcclusion::Wavefront::shadeRay(size_t r)
{
  const rt::RayQueue &rays = m_rays;
  const uint32_t i = rays.tag(r);
  const uint2 pixel = pixelOf(i);
  const rt::Hit hit = rays.hit(r);
  const Ray ray{rays.origin(r),
      rays.direction(r),
      rays.tMin(r),
      std::numeric_limits<float>::infinity(),
      m_times[i]};
  if (rays.untraceable(r))
    return; // the background stays
  // A volume before the hit absorbs the ray with the probability it
  // absorbs light (delta tracking): frames accumulate its emission.
  if (!m_context.world->volumes().empty()
      && collidesInVolume(i, ray, hit.found() ? hit.t : ray.tMax))
    return;
  SurfaceHit surface;
  if (!resolveSurfaceHit(
          *m_context.world, ray, hit, surface, HitDetail::ForMaterial))
    return; // the background stays
  const float4 base =
      surface.material().baseColorAndOpacity(surface.attributes);
  const float coverage = surface.material().coverage(base.w);
  if (coverage < 1.f
      && sobolSample2D(m_context.sampleIndex,
             sequenceSeed(pixel.x, pixel.y, 4 + m_layers[i], m_context.seed))
                 .x
             >= coverage) {
    if (++m_layers[i] < kMaxLayers) {
      m_next.push(ray.origin,
          ray.direction,
          hit.t + std::max(1e-4f, hit.t * 1e-5f),
          std::numeric_limits<float>::infinity(),
          ray.time,
          i);
    }
    return;
  }
  PixelSample &sample = m_samples[i];
  sample.color = float4{base.x, base.y, base.z, 1.f};
  recordSurfaceChannels(sample, hit.t, surface, float3{base.x, base.y, base.z});
  // Offset along the geometric normal, scaled with the distance, so
  // the occlusion rays do not hit the surface they start on.
  const float3 origin =
      surface.position
      + surface.geometricNormal * (1e-4f * std::max(1.f, hit.t));
  // Cosine-distributed directions around the shading normal.
  const LocalFrame hemisphere = LocalFrame::around(surface.shadingNormal);
  const uint32_t samples = m_renderer.m_samples;
  for (uint32_t k = 0; k < samples; k++) {
    const float2 u = sobolSample2D(m_context.sampleIndex * samples + k,
        sequenceSeed(pixel.x, pixel.y, 2, m_context.seed));
    m_occlusion.push(origin,
        hemisphere.toWorld(sampleCosineHemisphere(u)),
        0.f,
        m_renderer.m_distance,
        ray.time,
        i);
  }
}

void AmbientOcclusion::Wavefront::finish()
{
  m_context.transport->traceOcclusion(m_occlusion);
  for (size_t k = 0; k < m_occlusion.size(); k++)
    m_open[m_occlusion.tag(k)] += m_occlusion.transmittance(k).x;
  for (size_t i = 0; i < m_count; i++) {
    PixelSample &sample = m_samples[i];
    if (std::isfinite(sample.depth)) {
      const float visibility = m_open[i] / float(m_renderer.m_samples);
      sample.color = float4{sample.color.x * visibility,
          sample.color.y * visibility,
          sample.color.z * visibility,
          1.f};
    }
    const uint2 pixel = pixelOf(i);
    store(m_context, m_buffers, pixel.x, pixel.y, sample);
  }
}

void AmbientOcclusion::renderTile(const RenderContext &context,
    const Tile &tile,
    FrameBuffers &buffers,
    const std::atomic<bool> &cancel) const
{
  Wavefront work(*this, context, tile, buffers);
  runTile(work, tile, cancel);
}

} // namespace prism
