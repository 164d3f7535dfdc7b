#include "Raycast.h"

#include "TileLoop.h"

#include "PrimaryRays.h"
#include "SampleHash.h"
#include "VolumeTracing.h"

#include <algorithm>
#include <cmath>

namespace prism {
namespace {

// Surfaces seen through at most this many see-through layers per pixel.
constexpr int kMaxLayers = 64;
// Accumulated alpha beyond which the layers behind no longer show.
constexpr float kOpaqueAlpha = 0.999f;

// The eye light's brightness where the surface normal and the ray make an
// angle of the given cosine.
float eyeLight(float blendRatio, float cosine)
{
  return blendRatio * cosine + (1.f - blendRatio);
}

// Front-to-back compositing of the layers a ray crosses, then of the
// background behind them.
struct LayerBlend
{
  float3 color{0, 0, 0};
  float alpha{0.f};

  void add(const float3 &baseColor, float light, float coverage)
  {
    const float weight = (1.f - alpha) * coverage;
    color = color + baseColor * (light * weight);
    alpha += weight;
  }
  // A marched volume segment: its colour arrives attenuated already, its
  // opacity is what it absorbs of the light behind.
  void add(const VolumeMarch &march)
  {
    color = color + march.color * (1.f - alpha);
    alpha += (1.f - alpha) * (1.f - march.transmittance);
  }
  bool opaque() const
  {
    return alpha >= kOpaqueAlpha;
  }
  float4 over(const float4 &background) const
  {
    const float rest = 1.f - alpha;
    return {color.x + rest * background.x,
        color.y + rest * background.y,
        color.z + rest * background.z,
        alpha + rest * background.w};
  }
};

// What hits on one surface share when its material color is constant and
// its first layer is opaque: then a hit needs only its normal computed.
struct ConstantSurface
{
  uint32_t instanceKey{rt::kInvalidId}; // the hit ids this was made for
  uint32_t geometryKey{rt::kInvalidId};
  bool constant{false}; // false: shade the hit with shadeSample()
  bool flat{false};     // the shading normal is the normalised world-space Ng
  float3 baseColor{0, 0, 0};
  float coverage{0.f};
  uint32_t objectId{kNoId};
  uint32_t instanceId{kNoId};
};

// The ConstantSurface of the surface a hit names; `last` caches the one
// looked up before, as neighbouring pixels mostly hit the same surface.
const ConstantSurface &constantSurface(const World &world,
    uint32_t instanceKey,
    uint32_t geometryKey,
    ConstantSurface &last)
{
  if (last.instanceKey == instanceKey && last.geometryKey == geometryKey)
    return last;
  last = ConstantSurface{};
  last.instanceKey = instanceKey;
  last.geometryKey = geometryKey;
  const World::Placement &placement = world.placement(instanceKey);
  const Surface *surface = placement.group()->surface(geometryKey);
  if (!surface || surface->material()->colorReadsAttributes())
    return last;
  const Material &material = *surface->material();
  const float4 base = material.baseColorAndOpacity(AttributeValues{});
  last.baseColor = float3{base.x, base.y, base.z};
  last.coverage = material.coverage(base.w);
  LayerBlend first;
  first.add(last.baseColor, 1.f, last.coverage);
  last.constant = first.opaque();
  last.flat = last.constant && placement.identity()
              && surface->geometry()->flatShaded();
  last.objectId = surface->id();
  last.instanceId = placement.instanceId();
  return last;
}

// One packet's shading, lane by lane in arrays (SoA) so that the common
// case, a miss or a hit on a flat constant surface, is shaded for all
// lanes by one straight loop the compiler vectorises.
struct PacketShading
{
  static constexpr int kLanes = rt::kPacketSize;

  // Inputs. `hit` is 1 where the lane hit a flat constant surface, 0 where
  // it missed or is shaded by other means (then `otherwise` says so).
  alignas(32) float hit[kLanes];
  alignas(32) float baseR[kLanes], baseG[kLanes], baseB[kLanes];
  alignas(32) float coverage[kLanes];
  alignas(32) float backR[kLanes], backG[kLanes], backB[kLanes], backA[kLanes];
  uint32_t objectId[kLanes], instanceId[kLanes];
  bool otherwise[kLanes]; // shaded by other means into their PixelSample

  // Results of shadeFlat().
  alignas(32) float colorR[kLanes], colorG[kLanes], colorB[kLanes],
      colorA[kLanes];
  alignas(32) float normalX[kLanes], normalY[kLanes], normalZ[kLanes];

  void fillBackground(const float4 &background)
  {
    for (int i = 0; i < kLanes; i++) {
      backR[i] = background.x;
      backG[i] = background.y;
      backB[i] = background.z;
      backA[i] = background.w;
    }
  }
  // Lane i as a hit on `surface` (true) or as a miss.
  void setLane(int i, const ConstantSurface &surface, bool isHit)
  {
    hit[i] = isHit ? 1.f : 0.f;
    baseR[i] = isHit ? surface.baseColor.x : 0.f;
    baseG[i] = isHit ? surface.baseColor.y : 0.f;
    baseB[i] = isHit ? surface.baseColor.z : 0.f;
    coverage[i] = isHit ? surface.coverage : 0.f;
    objectId[i] = isHit ? surface.objectId : kNoId;
    instanceId[i] = isHit ? surface.instanceId : kNoId;
    otherwise[i] = false;
  }

  // What shadeSample() computes for flat hits and misses, operation for
  // operation: the shading normal is the normalised Ng turned to face the
  // ray; one layer is blended over the background, for a miss one of no
  // coverage (the lane's Ng is then meaningless and its light unused).
  void shadeFlat(const rt::RayHitPacket &packet, float blendRatio)
  {
    for (int i = 0; i < kLanes; i++) {
      const float gx = packet.normalX[i], gy = packet.normalY[i],
                  gz = packet.normalZ[i];
      const float inv = 1.f / std::sqrt(gx * gx + gy * gy + gz * gz);
      const float nx = gx * inv, ny = gy * inv, nz = gz * inv;
      const float facing = nx * packet.directionX[i] + ny * packet.directionY[i]
                           + nz * packet.directionZ[i];
      const bool away = facing > 0.f;
      normalX[i] = away ? nx * -1.f : nx;
      normalY[i] = away ? ny * -1.f : ny;
      normalZ[i] = away ? nz * -1.f : nz;
      // LayerBlend::add() on an empty blend; |facing| is also the turned
      // normal's, as negation is exact.
      const float weight = (1.f - 0.f) * coverage[i];
      const float lightWeight =
          hit[i] != 0.f ? eyeLight(blendRatio, std::abs(facing)) * weight : 0.f;
      const float alpha = 0.f + weight;
      // LayerBlend::over().
      const float rest = 1.f - alpha;
      colorR[i] = (0.f + baseR[i] * lightWeight) + rest * backR[i];
      colorG[i] = (0.f + baseG[i] * lightWeight) + rest * backG[i];
      colorB[i] = (0.f + baseB[i] * lightWeight) + rest * backB[i];
      colorA[i] = alpha + rest * backA[i];
    }
  }

  // Writes the first `count` lanes to row y from x0.
  void store(const rt::RayHitPacket &packet,
      FrameBuffers &buffers,
      uint32_t width,
      uint32_t x0,
      uint32_t y,
      int count) const
  {
    const size_t row = size_t(y) * width + x0;
    const FrameBuffers::Needs &needs = buffers.needs;
    float4 *color = buffers.color.data() + row;
    for (int i = 0; i < count; i++)
      color[i] = {colorR[i], colorG[i], colorB[i], colorA[i]};
    if (needs.depth) {
      for (int i = 0; i < count; i++) {
        buffers.depth[row + i] =
            hit[i] != 0.f ? packet.tMax[i] : PixelSample{}.depth;
      }
    }
    if (needs.normal) {
      for (int i = 0; i < count; i++) {
        buffers.normal[row + i] =
            hit[i] != 0.f ? float3{normalX[i], normalY[i], normalZ[i]}
                          : PixelSample{}.normal;
      }
    }
    if (needs.albedo) {
      for (int i = 0; i < count; i++)
        buffers.albedo[row + i] = {baseR[i], baseG[i], baseB[i]};
    }
    if (needs.primitiveId) {
      for (int i = 0; i < count; i++) {
        buffers.primitiveId[row + i] =
            hit[i] != 0.f ? packet.primitiveId[i] : kNoId;
      }
    }
    if (needs.objectId)
      std::copy(objectId, objectId + count, buffers.objectId.begin() + row);
    if (needs.instanceId) {
      std::copy(
          instanceId, instanceId + count, buffers.instanceId.begin() + row);
    }
  }
};

// One packet of camera rays as Embree traced it, with what tracing
// overwrites or does not keep. A local of each packet() call, as is the
// packet's shading: the compiler then knows that stores into the frame's
// buffers cannot change them, and need not reload them after each.
struct TracedPacket
{
  static constexpr int kLanes = rt::kPacketSize;

  rt::RayHitPacket rays;
  int active[kLanes];
  float rayTMax[kLanes]; // Embree overwrites the packet's with the hit's t
  // The lanes whose rays cross a volume before their hit.
  bool inVolume[kLanes] = {};

  Ray laneRay(int i) const
  {
    return Ray{{rays.originX[i], rays.originY[i], rays.originZ[i]},
        {rays.directionX[i], rays.directionY[i], rays.directionZ[i]},
        rays.tMin[i],
        rayTMax[i],
        rays.time[i]};
  }
  rt::Hit laneHit(int i) const
  {
    rt::Hit hit;
    hit.t = rays.tMax[i];
    hit.u = rays.u[i];
    hit.v = rays.v[i];
    hit.geometricNormal = {rays.normalX[i], rays.normalY[i], rays.normalZ[i]};
    hit.primitiveId = rays.primitiveId[i];
    hit.geometryId = rays.geometryId[i];
    hit.instanceId = rays.instanceId[i];
    return hit;
  }
  // Marks the first `count` lanes whose rays cross a volume before what
  // they hit; whether any does.
  bool markVolumes(const World &world, int count)
  {
    bool any = false;
    for (int i = 0; i < kLanes; i++) {
      const float end =
          rays.geometryId[i] == rt::kInvalidId ? rayTMax[i] : rays.tMax[i];
      inVolume[i] =
          i < count
          && mayMeetVolumes(world,
              {rays.originX[i], rays.originY[i], rays.originZ[i]},
              {rays.directionX[i], rays.directionY[i], rays.directionZ[i]},
              rays.tMin[i],
              end);
      any |= inVolume[i];
    }
    return any;
  }
};

} // namespace

void Raycast::commitParameters()
{
  Renderer::commitParameters();
  m_eyeLightBlendRatio = param<float>("eyeLightBlendRatio");
  m_volumeMajorantGrid = param<bool>("volumeMajorantGrid");
  // The SDK's experimental EXP_VOLUME_SAMPLE_RATE names the same factor
  // volumeSampleRateFactor; prism's own name wins when both are set.
  const float sdkRate = param<float>("volumeSampleRateFactor");
  const float ownRate = param<float>("volumeSamplingRate");
  m_volumeSamplingRate =
      isSet("volumeSamplingRate") || !isSet("volumeSampleRateFactor") ? ownRate
                                                                      : sdkRate;
}

// A tile's packets: traced whole, shaded by PacketShading, the lanes it
// cannot shade (see-through, textured, in volumes) by shadeSample(). Holds
// only what lasts the tile; each packet's state is local to packet().
class Raycast::Packets final : public TileWork
{
 public:
  Packets(const Raycast &renderer,
      const RenderContext &context,
      FrameBuffers &buffers)
      : m_renderer(renderer),
        m_context(context),
        m_world(*context.world),
        m_buffers(buffers),
        m_primaryRays(context),
        m_volumes(!m_world.volumes().empty()),
        m_uniformBackground(renderer.uniformBackground()),
        m_background(m_uniformBackground ? renderer.background(context, 0, 0)
                                         : float4{0.f, 0.f, 0.f, 0.f})
  {}

  void packet(uint32_t x0, uint32_t y, int count) override;

 private:
  static constexpr int kLanes = rt::kPacketSize;

  // Lane i of the packet just traced for the straight loop: a miss, a hit
  // on a flat constant surface, or a hit shaded here into m_samples[i],
  // the loop told to take it for a miss.
  void prepareLane(const TracedPacket &traced,
      PacketShading &shading,
      ConstantSurface &lastSurface,
      int i,
      uint32_t x0,
      uint32_t y);
  // The lanes' backgrounds.
  void fillBackgrounds(
      PacketShading &shading, uint32_t x0, uint32_t y, int count) const;

  const Raycast &m_renderer;
  const RenderContext &m_context;
  const World &m_world;
  FrameBuffers &m_buffers;
  const PrimaryRays m_primaryRays;
  const bool m_volumes;
  const bool m_uniformBackground;
  const float4 m_background;     // when uniform
  ConstantSurface m_lastSurface; // carried from packet to packet
  SurfaceHit m_surface; // reused for hits whose normal the geometry resolves
  PixelSample m_samples[kLanes]; // the lanes shaded otherwise
};

void Raycast::Packets::prepareLane(const TracedPacket &traced,
    PacketShading &shading,
    ConstantSurface &lastSurface,
    int i,
    uint32_t x0,
    uint32_t y)
{
  const uint32_t x = x0 + uint32_t(i);
  const rt::RayHitPacket &rays = traced.rays;
  if (traced.inVolume[i]) {
    shading.setLane(i, lastSurface, false);
    shading.otherwise[i] = true;
    m_samples[i] = m_renderer.shadeSample(
        m_context, traced.laneRay(i), traced.laneHit(i), x, y);
    return;
  }
  if (rays.geometryId[i] == rt::kInvalidId) {
    shading.setLane(i, lastSurface, false);
    return;
  }
  const ConstantSurface &constant = constantSurface(
      m_world, rays.instanceId[i], rays.geometryId[i], lastSurface);
  shading.setLane(i, constant, constant.flat);
  if (constant.flat)
    return;
  shading.otherwise[i] = true;
  const Ray ray = traced.laneRay(i);
  const rt::Hit hit = traced.laneHit(i);
  PixelSample &sample = m_samples[i];
  if (!constant.constant
      || !resolveSurfaceHit(
          m_world, ray, hit, m_surface, HitDetail::ForMaterial)) {
    sample = m_renderer.shadeSample(m_context, ray, hit, x, y);
    return;
  }
  // A constant surface whose normal the geometry resolves (spheres,
  // vertex normals, instances): just that is resolved per hit.
  LayerBlend blend;
  blend.add(constant.baseColor,
      eyeLight(m_renderer.m_eyeLightBlendRatio,
          std::abs(dot(m_surface.shadingNormal, ray.direction))),
      constant.coverage);
  sample.color = blend.over(
      {shading.backR[i], shading.backG[i], shading.backB[i], shading.backA[i]});
  sample.depth = hit.t;
  sample.normal = m_surface.shadingNormal;
  sample.albedo = constant.baseColor;
  sample.primitiveId = hit.primitiveId;
  sample.objectId = constant.objectId;
  sample.instanceId = constant.instanceId;
}

void Raycast::Packets::fillBackgrounds(
    PacketShading &shading, uint32_t x0, uint32_t y, int count) const
{
  if (m_uniformBackground) {
    shading.fillBackground(m_background);
    return;
  }
  // Idle lanes repeat the last pixel's, as PrimaryRays does their rays.
  for (int i = 0; i < kLanes; i++) {
    const uint32_t x = x0 + uint32_t(std::min(i, count - 1));
    const float4 b = m_renderer.background(m_context, x, y);
    shading.backR[i] = b.x;
    shading.backG[i] = b.y;
    shading.backB[i] = b.z;
    shading.backA[i] = b.w;
  }
}

void Raycast::Packets::packet(uint32_t x0, uint32_t y, int count)
{
  TracedPacket traced;
  rt::RayHitPacket &rays = traced.rays;
  m_primaryRays.generate(x0, y, count, rays, traced.active);
  std::copy(rays.tMax, rays.tMax + kLanes, traced.rayTMax);
  m_world.intersect(rays, traced.active);
  PacketShading shading;
  fillBackgrounds(shading, x0, y, count);
  ConstantSurface lastSurface = m_lastSurface;
  // Mostly every lane misses or hits the surface the last hit did.
  bool anyHit = false, sameSurface = true;
  for (int i = 0; i < kLanes; i++) {
    const bool isHit = rays.geometryId[i] != rt::kInvalidId;
    anyHit |= isHit;
    sameSurface &= !isHit
                   || (rays.geometryId[i] == lastSurface.geometryKey
                       && rays.instanceId[i] == lastSurface.instanceKey);
  }
  // Lanes whose rays cross a volume are marched (only if any can).
  const bool anyVolume = m_volumes && traced.markVolumes(m_world, count);
  if (sameSurface && (lastSurface.flat || !anyHit) && !anyVolume) {
    for (int i = 0; i < kLanes; i++)
      shading.setLane(i, lastSurface, rays.geometryId[i] != rt::kInvalidId);
  } else {
    for (int i = 0; i < kLanes; i++)
      prepareLane(traced, shading, lastSurface, i, x0, y);
    m_lastSurface = lastSurface;
  }
  shading.shadeFlat(rays, m_renderer.m_eyeLightBlendRatio);
  shading.store(rays, m_buffers, m_context.width, x0, y, count);
  for (int i = 0; i < count; i++) {
    if (shading.otherwise[i])
      store(m_context, m_buffers, x0 + uint32_t(i), y, m_samples[i]);
  }
}

void Raycast::renderTile(const RenderContext &context,
    const Tile &tile,
    FrameBuffers &buffers,
    const std::atomic<bool> &cancel) const
{
  Packets work(*this, context, buffers);
  runTile(work, tile, cancel);
}

PixelSample Raycast::shadeSample(const RenderContext &context,
    const Ray &ray,
    const rt::Hit &firstHit,
    uint32_t x,
    uint32_t y) const
{
  const World &world = *context.world;
  rt::Hit hit = firstHit;
  PixelSample sample;
  LayerBlend blend;
  bool first = true;
  // Volumes are marched between consecutive layers; their samples move
  // within their steps from frame to frame, so accumulation converges.
  MarchSettings march;
  march.samplingRate = m_volumeSamplingRate;
  march.offset = context.centredSample()
                     ? 0.5f
                     : hashedSample2D(x, y, context.sampleIndex, 7).x;
  // Without the majorant grid: the reference marcher, every step sampled.
  march.skipEmpty = m_volumeMajorantGrid;
  march.stopTransmittance = m_volumeMajorantGrid ? 1.f - kOpaqueAlpha : 0.f;
  float marchedTo = ray.tMin;
  auto marchTo = [&](float end) {
    if (world.volumes().empty() || (blend.opaque() && m_volumeMajorantGrid))
      return;
    const VolumeMarch segment =
        marchVolumes(world, ray.origin, ray.direction, marchedTo, end, march);
    marchedTo = end;
    if (first && segment.firstDepth < end) {
      sample.depth = segment.firstDepth;
      sample.albedo = segment.firstColor;
      sample.objectId = segment.objectId;
      sample.instanceId = segment.instanceId;
      first = false;
    }
    blend.add(segment);
  };
  for (int layer = 0; layer < kMaxLayers && hit.found(); layer++) {
    marchTo(hit.t);
    if (blend.opaque())
      break;
    SurfaceHit surface;
    if (resolveSurfaceHit(world, ray, hit, surface, HitDetail::ForMaterial)) {
      const float4 base =
          surface.material().baseColorAndOpacity(surface.attributes);
      const float coverage = surface.material().coverage(base.w);
      if (coverage > 0.f) {
        if (first) {
          recordSurfaceChannels(
              sample, hit.t, surface, float3{base.x, base.y, base.z});
          first = false;
        }
        blend.add(float3{base.x, base.y, base.z},
            eyeLight(m_eyeLightBlendRatio,
                std::abs(dot(surface.shadingNormal, ray.direction))),
            coverage);
        if (blend.opaque())
          break;
      }
    }
    hit = traceBeyond(world, ray, hit);
  }
  if (!hit.found())
    marchTo(ray.tMax);
  sample.color = blend.over(background(context, x, y));
  return sample;
}

} // namespace prism
