#include "PathTracer.h"

#include "TileLoop.h"

#include "NormalMapping.h"

#include "../light/EmissiveSurface.h"
#include "../light/PlacedLight.h"
#include "../material/Material.h"
#include "../parallel/Blocks.h"
#include "../shading/Bsdf.h"
#include "../shading/Sampling.h"
#include "SampleSequence.h"
#include "VolumeTracing.h"
#include "wavefront/BounceDecisions.h"
#include "wavefront/RayTransport.h"
#include "wavefront/WavefrontTile.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

namespace prism {
namespace {

// Random streams: kStreamsPerBounce per bounce (BounceDecisions);
// see-through surfaces draw from kOpacityStreams on.
constexpr uint32_t kOpacityStreams = 0x10000u;
// Collisions in volumes draw from kVolumeStreams on.
constexpr uint32_t kVolumeStreams = 0x20000u;
// See-through surfaces a path passes at one bounce before it gives up.
constexpr uint16_t kMaxLayers = 64;

// One coordinate of decision `stream` of the path (streamSeed), for the
// decisions only some rays make (see-through surfaces).
float randomX(const PathState &path, uint32_t stream)
{
  return sobolSampleX(path.sampleIndex, streamSeed(path, stream));
}

// False when the ray (unit `direction`) surely passes the light's bounds
// within (tMin, hitDistance): a few multiplies instead of asking the light.
// The sphere is widened by more than the rounding of this test, so every
// ray that can find the light is let through.
bool mayReach(const World::ReachableLight &light,
    const float3 &origin,
    const float3 &direction,
    float tMin,
    float hitDistance)
{
  if (!light.bounded)
    return true;
  const float3 toCenter = light.bounds.center - origin;
  const float along = dot(toCenter, direction);
  const float radius = light.bounds.radius * 1.001f + 1e-5f * std::abs(along);
  if (along + radius <= tMin || along - radius >= hitDistance)
    return false;
  // The distance of the line from the center, without cancellation.
  const float3 across = toCenter - direction * along;
  return lengthSquared(across) <= radius * radius;
}

// Delta tracking through the world's volumes along the ray from `origin`
// between tMin and tMax: the path's own random numbers, salted per process
// (RayTransport::mediaStreamSalt), so whichever process samples a ray's
// collisions samples the same ones.
bool sampleCollision(const World &world,
    const PathState &path,
    const float3 &origin,
    const float3 &direction,
    float tMin,
    float tMax,
    uint32_t salt,
    bool majorantGrid,
    VolumeCollision &collision)
{
  HashedStream random(
      streamSeed(path, kVolumeStreams + path.layer + 97u * path.bounce)
      ^ mixBits(path.sampleIndex) ^ salt);
  return trackCollision(
      world, origin, direction, tMin, tMax, random, collision, majorantGrid);
}

// The collisions this process's volumes put before each ray's hit, for a
// transport that decides across processes who shades a ray; shadeBounce
// samples the same ones again on the process that does.
class QueueMedia final : public MediaEvents
{
 public:
  QueueMedia(const RenderContext &context,
      const std::vector<PathState> &paths,
      const rt::RayQueue &rays,
      bool majorantGrid)
      : m_context(context),
        m_paths(paths),
        m_rays(rays),
        m_majorantGrid(majorantGrid)
  {}

  float collisionBefore(size_t r, float hitDistance) const override
  {
    VolumeCollision collision;
    if (m_rays.untraceable(r)
        || !sampleCollision(*m_context.world,
            m_paths[m_rays.tag(r)],
            m_rays.origin(r),
            m_rays.direction(r),
            m_rays.tMin(r),
            hitDistance,
            m_context.transport->mediaStreamSalt(),
            m_majorantGrid,
            collision))
      return std::numeric_limits<float>::infinity();
    return collision.t;
  }

 private:
  const RenderContext &m_context;
  const std::vector<PathState> &m_paths;
  const rt::RayQueue &m_rays;
  bool m_majorantGrid;
};

float3 exp3(const float3 &v)
{
  return {std::exp(v.x), std::exp(v.y), std::exp(v.z)};
}

} // namespace

void PathTracer::commitParameters()
{
  Renderer::commitParameters();
  m_maxPathLength = param<int32_t>("maxPathLength");
  m_ambient = m_ambientColor * std::max(m_ambientRadiance, 0.f);
  m_volumeMajorantGrid = param<bool>("volumeMajorantGrid");
  m_seed = uint32_t(param<int32_t>("seed"));
}

// A tile's paths advancing bounce by bounce: each bounce's rays traced as
// one queue, then its shadow rays as another.
class PathTracer::Wavefront final : public WavefrontTile<TileWorkspace>
{
 public:
  Wavefront(const PathTracer &renderer,
      const RenderContext &context,
      const Tile &tile,
      FrameBuffers &buffers)
      : WavefrontTile(context, tile, buffers, renderer.m_workspaces),
        m_renderer(renderer),
        m_volumes(!context.world->volumes().empty())
  {
    m_workspace->paths.resize(m_count);
    m_workspace->cameraRays.resize(m_count);
  }

  // Starts the packet's paths and makes their camera rays.
  void packet(uint32_t x0, uint32_t y, int count) override;
  bool packetsInParallel() const override
  {
    return true; // each pixel's path and ray on its own
  }
  bool bounce() override;
  void finish() override;

 private:
  // Queues the camera rays in pixel order, before the first bounce.
  void queueCameraRays();
  // Adds what the shadow rays that reached their lights bring.
  void traceShadows();

  const PathTracer &m_renderer;
  const bool m_volumes;
  bool m_queued{false};
};

void PathTracer::Wavefront::packet(uint32_t x0, uint32_t y, int count)
{
  std::vector<PathState> &paths = m_workspace->paths;
  std::vector<Ray> &cameraRays = m_workspace->cameraRays;
  const size_t first = indexOf(x0, y);
  for (size_t i = first; i < first + size_t(count); i++) {
    PathState &path = paths[i];
    path = PathState{};
    const uint2 pixel = pixelOf(i);
    path.x = pixel.x;
    path.y = pixel.y;
    path.seed = sequenceSeed(path.x, path.y, 0, m_context.seed);
    path.sampleIndex = m_context.sampleIndex;
    cameraRays[i] = m_context.cameraRay(path.x, path.y);
    path.time = cameraRays[i].time;
  }
}

void PathTracer::Wavefront::queueCameraRays()
{
  rt::RayQueue &rays = m_workspace->rays;
  rays.clear();
  for (size_t i = 0; i < m_count; i++) {
    const Ray &ray = m_workspace->cameraRays[i];
    rays.push(
        ray.origin, ray.direction, ray.tMin, ray.tMax, ray.time, uint32_t(i));
  }
  rays.setCoherent(true);
  m_queued = true;
}

bool PathTracer::Wavefront::bounce()
{
  if (!m_queued)
    queueCameraRays();
  rt::RayQueue &rays = m_workspace->rays;
  if (rays.empty())
    return false;
  std::vector<PathState> &paths = m_workspace->paths;
  BounceQueues &queued = m_workspace->queued;
  m_renderer.m_raysTraced.fetch_add(rays.size(), std::memory_order_relaxed);
  const QueueMedia media(
      m_context, paths, rays, m_renderer.m_volumeMajorantGrid);
  m_context.transport->traceClosest(rays, m_volumes ? &media : nullptr);
  m_renderer.shadeBounce(m_context,
      paths,
      rays,
      m_workspace->decisions,
      queued,
      m_workspace->blocks);
  m_context.transport->shareBounce(
      paths, rays, queued.next, queued.shadows, queued.contributions);
  traceShadows();
  std::swap(rays, queued.next);
  return true;
}

void PathTracer::Wavefront::traceShadows()
{
  BounceQueues &queued = m_workspace->queued;
  rt::RayQueue &shadows = queued.shadows;
  if (shadows.empty())
    return;
  m_renderer.m_raysTraced.fetch_add(shadows.size(), std::memory_order_relaxed);
  m_context.transport->traceOcclusion(shadows);
  for (size_t k = 0; k < shadows.size(); k++) {
    const float3 &through = shadows.transmittance(k);
    if (maxComponent(through) > 0.f) {
      PathState &path = m_workspace->paths[shadows.tag(k)];
      const ShadowContribution &c = queued.contributions[k];
      const float weight =
          std::isinf(shadows.passedOneSidedAt(k)) ? c.weight : 1.f;
      path.radiance = path.radiance + c.radiance * through * weight;
    }
  }
}

void PathTracer::Wavefront::finish()
{
  std::vector<PathState> &paths = m_workspace->paths;
  forEachBlock(m_count, 1024, [&](size_t begin, size_t size) {
    for (size_t i = begin; i < begin + size; i++) {
      PathState &path = paths[i];
      // Else the background, already stored by shadeBounce.
      if (path.recordedFirstHit || path.bounce > 0)
        path.sample.color =
            float4{path.radiance.x, path.radiance.y, path.radiance.z, 1.f};
      store(m_context, m_buffers, path.x, path.y, path.sample);
    }
  });
}

void PathTracer::renderTile(const RenderContext &context,
    const Tile &tile,
    FrameBuffers &buffers,
    const std::atomic<bool> &cancel) const
{
  Wavefront work(*this, context, tile, buffers);
  runTile(work, tile, cancel);
}

float PathTracer::emissionWeight(
    const RenderContext &context, const PathState &path, const Bounce &b) const
{
  // Camera rays and delta bounces could not have sampled the surface.
  if (path.bounce == 0 || path.previousDelta)
    return 1.f;
  const World &world = *context.world;
  const rt::Hit &hit = b.hit;
  const Ray &ray = b.ray;
  const int32_t index = world.emitterLight(hit.instanceId, hit.geometryId);
  if (index < 0)
    return 1.f; // no light samples this surface
  if (b.passedOneSided < hit.t)
    return 0.f; // its light meets a single-sided surface's front on the way
  const SurfaceHit &surface = b.surface;
  const auto &emitter =
      static_cast<const EmissiveSurface &>(*world.lights()[size_t(index)]);
  const float cosine = std::abs(dot(surface.geometricNormal, ray.direction));
  const float lightPdf = emitter.pdfOfHit(ray.origin,
                             path.previousNormal,
                             ray.direction,
                             hit.primitiveId,
                             hit.t,
                             cosine)
                         * world.lightSelector().probability(size_t(index));
  return powerHeuristic(1, path.previousPdf, 1, lightPdf);
}

bool PathTracer::getProperty(const std::string &name,
    ANARIDataType type,
    void *mem,
    uint64_t size,
    ANARIWaitMask mask)
{
  if (name == "raysTraced" && type == ANARI_UINT64 && mem
      && size >= sizeof(uint64_t)) {
    const uint64_t value = m_raysTraced.load(std::memory_order_relaxed);
    std::memcpy(mem, &value, sizeof(value));
    return true;
  }
  return Renderer::getProperty(name, type, mem, size, mask);
}

float3 PathTracer::lightsAlong(const RenderContext &context,
    const float3 &origin,
    const float3 &direction,
    float tMin,
    float hitDistance,
    float passedOneSided,
    const PathState &path) const
{
  const auto &lights = context.world->lights();
  const LightSelector &selector = context.world->lightSelector();
  const bool cameraRay = path.bounce == 0;
  float3 sum{0.f, 0.f, 0.f};
  for (const World::ReachableLight &reachable :
      context.world->lightsReachableByRays()) {
    const uint32_t i = reachable.index;
    const PlacedLight &light = *lights[i];
    if ((cameraRay && !light.visibleToCamera)
        || !mayReach(reachable, origin, direction, tMin, hitDistance))
      continue;
    float distance = 0.f, lightPdf = 0.f;
    const float3 radiance = light.radianceAlongFacing(
        origin, path.previousNormal, direction, distance, lightPdf);
    // Lights at infinity (distance +inf) are behind every surface and
    // reached by every ray that escapes (hitDistance +inf).
    const bool hidden = std::isfinite(hitDistance) && distance >= hitDistance;
    if (distance <= tMin || hidden || maxComponent(radiance) <= 0.f)
      continue;
    // Camera rays and delta bounces could not have sampled the light; a
    // shadow ray would have found it blocked past a single-sided
    // surface's back.
    float weight = 1.f;
    if (!cameraRay && !path.previousDelta) {
      weight =
          distance > passedOneSided
              ? 0.f
              : powerHeuristic(
                  1, path.previousPdf, 1, lightPdf * selector.probability(i));
    }
    sum = sum + radiance * weight;
  }
  return sum;
}

void PathTracer::BounceQueues::clear()
{
  next.clear();
  shadows.clear();
  contributions.clear();
}

void PathTracer::BounceQueues::append(const BounceQueues &more)
{
  next.append(more.next);
  shadows.append(more.shadows);
  contributions.insert(contributions.end(),
      more.contributions.begin(),
      more.contributions.end());
}

void PathTracer::shadeBounce(const RenderContext &context,
    std::vector<PathState> &paths,
    const rt::RayQueue &rays,
    BounceDecisions &decisions,
    BounceQueues &out,
    std::vector<BounceQueues> &blocks) const
{
  decisions.draw(paths, rays);
  out.clear();
  // A tile's wavefront (32 x 32 rays): shaded here, straight into `out`.
  constexpr size_t kBlock = 1024;
  if (rays.size() <= kBlock) {
    shadeRays(context, paths, rays, 0, rays.size(), decisions, out);
    return;
  }
  // Each ray touches only its own path, so blocks shade side by side.
  const size_t count = (rays.size() + kBlock - 1) / kBlock;
  if (blocks.size() < count)
    blocks.resize(count);
  forEachBlock(rays.size(), kBlock, [&](size_t begin, size_t size) {
    BounceQueues &block = blocks[begin / kBlock];
    block.clear();
    shadeRays(context, paths, rays, begin, begin + size, decisions, block);
  });
  for (size_t b = 0; b < count; b++)
    out.append(blocks[b]);
}

void PathTracer::shadeRays(const RenderContext &context,
    std::vector<PathState> &paths,
    const rt::RayQueue &rays,
    size_t begin,
    size_t end,
    const BounceDecisions &decisions,
    BounceQueues &out) const
{
  rt::RayQueue &next = out.next, &shadows = out.shadows;
  std::vector<ShadowContribution> &contributions = out.contributions;
  // Reused ray after ray: building them afresh zeroed half a kilobyte a
  // ray. resolveHit fills what each ray reads.
  SurfaceHit surface;
  MaterialShading shading;
  std::optional<Bsdf> bsdf;
  const uint8_t *shaded = context.transport->shadedRays();
  for (size_t r = begin; r < end; r++) {
    if (rays.untraceable(r))
      continue; // a degenerate camera or bounce ray ends its path
    if (shaded && !shaded[r])
      continue; // another process owns the hit
    Bounce b =
        resolveHit(context, paths[rays.tag(r)], rays, r, surface, shading);
    if (collidesInVolume(context, b))
      continue;
    emitAlongRay(context, b);
    if (!b.found || passThrough(b, next))
      continue;
    recordFirstHit(b);
    emitFromSurface(context, b);
    // The last surface a path may meet is still lit directly (its light
    // sample then weighs fully: no BSDF sample follows to share it with).
    const bool last = b.path.bounce + 1 >= m_maxPathLength;
    const Scattering scattering = scatteringAt(b, bsdf);
    nextEvent(context, b, scattering, decisions, last, shadows, contributions);
    if (!last)
      scatter(b, scattering, decisions, next);
  }
}

PathTracer::Bounce PathTracer::resolveHit(const RenderContext &context,
    PathState &path,
    const rt::RayQueue &rays,
    size_t r,
    SurfaceHit &surface,
    MaterialShading &shading) const
{
  Bounce b{path,
      rays.tag(r),
      r,
      Ray{rays.origin(r), rays.direction(r)},
      rays.tMin(r),
      rays.hit(r),
      rays.passedOneSidedAt(r),
      false,
      surface};
  b.ray.time = path.time;
  b.found = b.hit.found()
            && resolveSurfaceHit(
                *context.world, b.ray, b.hit, b.surface, HitDetail::ForShading);
  if (b.found) {
    const Material &material = b.surface.material();
    if (const ConstantShading *constant = material.constantShading()) {
      b.shading = &constant->shading;
      b.constantBsdf = &constant->bsdf;
    } else {
      shading = material.shade(b.surface.attributes);
      b.shading = &shading;
    }
  }
  return b;
}

bool PathTracer::collidesInVolume(const RenderContext &context, Bounce &b) const
{
  const World &world = *context.world;
  if (world.volumes().empty())
    return false;
  PathState &path = b.path;
  const float hitDistance =
      b.hit.found() ? b.hit.t : std::numeric_limits<float>::infinity();
  VolumeCollision collision;
  if (!sampleCollision(world,
          path,
          b.ray.origin,
          b.ray.direction,
          b.tMin,
          hitDistance,
          context.transport->mediaStreamSalt(),
          m_volumeMajorantGrid,
          collision))
    return false;
  // The volume absorbed the path there and emits its colour (the media of
  // spec 5.12.1 absorb and emit; they do not scatter).
  path.radiance = path.radiance + path.throughput * collision.color;
  if (!path.recordedFirstHit) {
    path.sample.depth = collision.t;
    path.sample.albedo = collision.color;
    path.sample.objectId = collision.objectId;
    path.sample.instanceId = collision.instanceId;
    path.recordedFirstHit = true;
  }
  return true;
}

void PathTracer::emitAlongRay(const RenderContext &context, Bounce &b) const
{
  PathState &path = b.path;
  const float hitDistance =
      b.found ? b.hit.t : std::numeric_limits<float>::infinity();
  // Inside an absorbing medium: Beer-Lambert over the segment.
  if (b.found && path.media.depth() > 0) {
    const float3 absorption = path.media.absorption();
    if (maxComponent(absorption) > 0.f)
      path.throughput = path.throughput * exp3(absorption * -b.hit.t);
  }
  path.radiance = path.radiance
                  + path.throughput
                        * lightsAlong(context,
                            b.ray.origin,
                            b.ray.direction,
                            b.tMin,
                            hitDistance,
                            b.passedOneSided,
                            path);
  if (b.found)
    return;
  if (path.bounce == 0 && !path.recordedFirstHit) {
    const float4 bg = background(context, path.x, path.y);
    path.sample.color = float4{path.radiance.x + bg.x,
        path.radiance.y + bg.y,
        path.radiance.z + bg.z,
        bg.w};
  } else {
    path.radiance =
        path.radiance + path.throughput * m_ambient * path.ambientVisibility;
  }
}

bool PathTracer::passThrough(Bounce &b, rt::RayQueue &next) const
{
  // See-through surfaces: pass through with probability 1 - opacity (each
  // layer its own random number).
  PathState &path = b.path;
  if (!(b.shading->opacity < 1.f)
      || randomX(path, kOpacityStreams + path.layer + 97u * path.bounce)
             < b.shading->opacity) {
    path.layer = 0;
    return false;
  }
  if (++path.layer < kMaxLayers) {
    const size_t r = next.push(b.ray.origin,
        b.ray.direction,
        b.hit.t + std::max(1e-4f, b.hit.t * 1e-5f),
        std::numeric_limits<float>::infinity(),
        path.time,
        b.tag);
    // The same ray on: a single-sided face it passed before this layer
    // still stands between its origin and what it finds next.
    next.setPassedOneSidedAt(r, b.passedOneSided);
  }
  return true;
}

void PathTracer::recordFirstHit(Bounce &b) const
{
  PathState &path = b.path;
  if (path.recordedFirstHit)
    return;
  recordSurfaceChannels(path.sample, b.hit.t, b.surface, b.shading->albedo);
  path.recordedFirstHit = true;
}

void PathTracer::emitFromSurface(const RenderContext &context, Bounce &b) const
{
  const float3 &emissive = b.shading->emissive;
  if (emissive.x == 0.f && emissive.y == 0.f && emissive.z == 0.f)
    return; // most surfaces: nothing to weigh
  PathState &path = b.path;
  path.radiance =
      path.radiance
      + path.throughput * emissive * emissionWeight(context, path, b);
}

PathTracer::Scattering PathTracer::scatteringAt(
    const Bounce &b, std::optional<Bsdf> &storage) const
{
  // The local shading frame around the geometry's own (unflipped) shading
  // normal: the BSDF needs to know which side the viewer is on to tell
  // entering a medium from leaving it.
  const SurfaceHit &surface = b.surface;
  const float3 towardsViewer = b.ray.direction * -1.f;
  const float3 unbent =
      surface.backFacing ? surface.shadingNormal * -1.f : surface.shadingNormal;
  const MaterialShading &shading = *b.shading;
  const float3 normal =
      shading.hasNormalMap ? normalMapped(
          surface, b.hit, unbent, shading.normalMap, towardsViewer)
                           : unbent;
  const LocalFrame frame = LocalFrame::around(normal);
  const Bsdf *bsdf = b.constantBsdf;
  if (!bsdf) {
    BsdfInputs inputs = shading.bsdf;
    // The coat's normal map bends the geometry's normal on its own.
    if (shading.hasCoatNormalMap)
      inputs.clearcoatNormal = frame.toLocal(normalMapped(
          surface, b.hit, unbent, shading.coatNormalMap, towardsViewer));
    // The anisotropy's direction, from tangent space to ours.
    float3 tangent, bitangent;
    if (inputs.anisotropy > 0.f
        && tangentFrame(surface, b.hit, normal, tangent, bitangent)) {
      const float3 local =
          frame.toLocal(tangent * shading.anisotropyDirection.x
                        + bitangent * shading.anisotropyDirection.y);
      inputs.anisotropyDirection = {local.x, local.y};
    }
    bsdf = &storage.emplace(inputs);
  }
  const float3 ng = surface.geometricNormal;
  const float3 receiver =
      bsdf->hasTransmission() || bsdf->isVolumeBoundary()
          ? float3{0.f, 0.f, 0.f}
          : (dot(b.ray.direction, ng) < 0.f ? ng : ng * -1.f);
  return Scattering{frame,
      *bsdf,
      frame.toLocal(towardsViewer),
      1e-4f * std::max(1.f, b.hit.t),
      receiver};
}

void PathTracer::nextEvent(const RenderContext &context,
    const Bounce &b,
    const Scattering &scattering,
    const BounceDecisions &decisions,
    bool last,
    rt::RayQueue &shadows,
    std::vector<ShadowContribution> &contributions) const
{
  // One light, chosen by power; its shadow ray joins the bounce's shadow
  // queue, its contribution counts if nothing blocks it.
  const LightSelector &selector = context.world->lightSelector();
  const Bsdf &bsdf = scattering.bsdf;
  if (selector.empty() || !bsdf.hasNonDeltaLobes())
    return;
  const PathState &path = b.path;
  float pickProbability = 0.f;
  const PlacedLight &light = *context.world->lights()[selector.pick(
      decisions.lightPick(b.rayIndex), pickProbability)];
  const LightSample ls = light.sampleFacing(b.surface.position,
      scattering.receiverNormal,
      decisions.lightPoint(b.rayIndex));
  if (!(ls.pdf > 0.f) || !(maxComponent(ls.radiance) > 0.f))
    return;
  const float3 wi = scattering.frame.toLocal(ls.direction);
  float3 f;
  float bsdfPdf = 0.f;
  bsdf.evalAndPdf(scattering.wo, wi, f, bsdfPdf);
  if (!(maxComponent(f) > 0.f))
    return;
  const float3 ng = b.surface.geometricNormal;
  const float3 side = dot(ls.direction, ng) > 0.f ? ng : ng * -1.f;
  const float tMax = std::isinf(ls.distance)
                         ? ls.distance
                         : ls.distance * (1.f - 1e-4f) - scattering.offset;
  const float pdf = ls.pdf * pickProbability;
  const float weight =
      ls.delta || last ? 1.f : powerHeuristic(1, pdf, 1, bsdfPdf);
  shadows.push(b.surface.position + side * scattering.offset,
      ls.direction,
      0.f,
      std::max(tMax, 0.f),
      path.time,
      b.tag);
  contributions.push_back(
      {path.throughput * f * ls.radiance * (std::abs(wi.z) / pdf), weight});
}

void PathTracer::scatter(Bounce &b,
    const Scattering &scattering,
    const BounceDecisions &decisions,
    rt::RayQueue &next) const
{
  // Continue the path by sampling the BSDF.
  PathState &path = b.path;
  const Bsdf &bsdf = scattering.bsdf;
  const BsdfSample bs = bsdf.sample(scattering.wo,
      decisions.direction(b.rayIndex),
      bsdf.choosesLobes() ? decisions.lobe(b.rayIndex) : 0.f);
  // A black BSDF (e.g. an unlit surface) ends the path.
  if (!bs.valid() || !(maxComponent(bs.weight) > 0.f))
    return;
  path.throughput = path.throughput * bs.weight;
  path.previousPdf = bs.pdf;
  path.previousNormal = scattering.receiverNormal;
  path.previousDelta = bs.isDelta();
  path.ambientVisibility = b.shading->occlusion;
  const float3 normal = scattering.frame.z;
  const float3 wi = normalize(scattering.frame.toWorld(bs.wi));
  // Crossing a volume boundary: entering it (against the unflipped
  // normal) enters its medium, leaving it returns to the one outside.
  if (bsdf.isVolumeBoundary()
      && dot(wi, normal) * dot(b.ray.direction, normal) > 0.f) {
    if (dot(wi, normal) < 0.f)
      path.media.enter(b.shading->attenuation);
    else
      path.media.leave();
  }
  path.bounce++;
  if (!survivesRoulette(path, decisions.roulette(b.rayIndex)))
    return;
  const float3 ng = b.surface.geometricNormal;
  const float3 side = dot(wi, ng) > 0.f ? ng : ng * -1.f;
  next.push(b.surface.position + side * scattering.offset,
      wi,
      0.f,
      std::numeric_limits<float>::infinity(),
      path.time,
      b.tag);
}

bool PathTracer::survivesRoulette(PathState &path, float u) const
{
  // After three bounces a path goes on with probability (at most 0.95) the
  // square root of its throughput and is weighted up when it does: long
  // paths unbiased. The root, not the throughput itself: a survivor's
  // throughput becomes the root, so in a room of albedo a paths go on with
  // sqrt(a) a bounce rather than a, and the light deep bounces still carry
  // in closed rooms costs fewer paths cut short (the Cornell box reaches
  // equal error 8 % sooner; see bench/README.md).
  if (path.bounce <= kFirstRouletteBounce)
    return true;
  const float survive =
      std::min(0.95f, std::sqrt(maxComponent(path.throughput)));
  if (u >= survive)
    return false;
  path.throughput = path.throughput / survive;
  return true;
}

} // namespace prism
