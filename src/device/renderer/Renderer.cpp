#include "Renderer.h"

#include "PrimaryRays.h"
#include "TileLoop.h"

#include "../array/Array.h"
#include "../array/ElementConversion.h"
#include "../introspection/Introspection.h"
#include "../object/DeviceState.h"
#include "ImageFilter.h"

#include "anari/frontend/type_utility.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace prism {

Renderer::Renderer(DeviceState &device, const std::string &subtype)
    : Object(device, ANARI_RENDERER, subtype)
{}

void Renderer::commitParameters()
{
  // KHR_RENDERER_AMBIENT_LIGHT: the path tracer lights with it; the other
  // renderers show geometry, not lighting, and take it without using it.
  m_ambientColor = param<float3>("ambientColor");
  m_ambientRadiance = param<float>("ambientRadiance");
  m_denoise = param<bool>("denoise");
  m_sampleLimit = uint32_t(param<int32_t>("sampleLimit"));
  m_pixelSamples = uint32_t(std::max(param<int32_t>("pixelSamples"), 1));
  m_errorThreshold = param<float>("errorThreshold");
  m_backgroundColor = {0, 0, 0, 1};
  m_backgroundImage.clear();
  m_backgroundWidth = m_backgroundHeight = 0;
  const Parameter *background = readAny("background");
  if (!background)
    return;
  if (background->type() == ANARI_FLOAT32_VEC4) {
    m_backgroundColor = background->as<float4>();
  } else if (background->type() == ANARI_FLOAT32_VEC3) {
    const auto rgb = background->as<float3>();
    m_backgroundColor = {rgb.x, rgb.y, rgb.z, 1.f};
  } else if (background->type() == ANARI_ARRAY2D) {
    auto *image = (const Array *)background->object();
    if (!canReadAsFloat4(image->elementType())) {
      report(ANARI_SEVERITY_WARNING,
          ANARI_STATUS_INVALID_ARGUMENT,
          "'background' image of element type %s is not a color; ignored",
          anari::toString(image->elementType()));
      return;
    }
    m_backgroundWidth = uint32_t(image->size(0));
    m_backgroundHeight = uint32_t(image->size(1));
    m_backgroundImage.resize(size_t(m_backgroundWidth) * m_backgroundHeight);
    convertToFloat4(image->elementType(),
        image->begin(),
        m_backgroundImage.size(),
        image->elementSize(),
        m_backgroundImage.data());
  } else {
    wrongType("background",
        background->type(),
        {ANARI_FLOAT32_VEC4, ANARI_FLOAT32_VEC3, ANARI_ARRAY2D});
  }
}

float4 Renderer::background(
    uint32_t x, uint32_t y, uint32_t width, uint32_t height) const
{
  if (m_backgroundImage.empty())
    return m_backgroundColor;
  return sampleBilinear(m_backgroundImage.data(),
      m_backgroundWidth,
      m_backgroundHeight,
      (float(x) + 0.5f) / float(width),
      (float(y) + 0.5f) / float(height));
}

// The default tile: each packet's primary rays traced together, each
// pixel shaded by the renderer's shadeSample() and stored.
class Renderer::PrimaryPackets final : public TileWork
{
 public:
  PrimaryPackets(const Renderer &renderer,
      const RenderContext &context,
      FrameBuffers &buffers)
      : m_renderer(renderer),
        m_context(context),
        m_buffers(buffers),
        m_primaryRays(context)
  {}

  void packet(uint32_t x0, uint32_t y, int count) override
  {
    m_renderer.tracePrimary(
        m_context, m_primaryRays, x0, y, count, m_rays, m_hits);
    for (int i = 0; i < count; i++) {
      store(m_context,
          m_buffers,
          x0 + i,
          y,
          m_renderer.shadeSample(m_context, m_rays[i], m_hits[i], x0 + i, y));
    }
  }

 private:
  const Renderer &m_renderer;
  const RenderContext &m_context;
  FrameBuffers &m_buffers;
  const PrimaryRays m_primaryRays;
  Ray m_rays[rt::kPacketSize];
  rt::Hit m_hits[rt::kPacketSize];
};

void Renderer::renderTile(const RenderContext &context,
    const Tile &tile,
    FrameBuffers &buffers,
    const std::atomic<bool> &cancel) const
{
  PrimaryPackets work(*this, context, buffers);
  runTile(work, tile, cancel);
}

PixelSample Renderer::shadeSample(const RenderContext &context,
    const Ray &,
    const rt::Hit &,
    uint32_t x,
    uint32_t y) const
{
  PixelSample sample;
  sample.color = background(context, x, y);
  return sample;
}

void Renderer::tracePrimary(const RenderContext &context,
    const PrimaryRays &primaryRays,
    uint32_t x0,
    uint32_t y,
    int count,
    Ray rays[rt::kPacketSize],
    rt::Hit hits[rt::kPacketSize]) const
{
  rt::RayHitPacket packet;
  alignas(32) int active[rt::kPacketSize];
  primaryRays.generate(x0, y, count, packet, active);
  for (int i = 0; i < count; i++) {
    rays[i] = Ray{{packet.originX[i], packet.originY[i], packet.originZ[i]},
        {packet.directionX[i], packet.directionY[i], packet.directionZ[i]},
        packet.tMin[i],
        packet.tMax[i],
        packet.time[i]};
  }
  context.world->intersect(packet, active);
  for (int i = 0; i < count; i++) {
    rt::Hit &hit = hits[i];
    hit = rt::Hit{};
    if (packet.geometryId[i] == rt::kInvalidId)
      continue;
    hit.t = packet.tMax[i];
    hit.u = packet.u[i];
    hit.v = packet.v[i];
    hit.geometricNormal = {
        packet.normalX[i], packet.normalY[i], packet.normalZ[i]};
    hit.primitiveId = packet.primitiveId[i];
    hit.geometryId = packet.geometryId[i];
    hit.instanceId = packet.instanceId[i];
  }
}

Ray RenderContext::cameraRay(uint32_t x, uint32_t y) const
{
  const float2 offset = offsetInPixel(x, y);
  // Multiplying by the reciprocal, as the pinhole fast path does, keeps
  // both paths' rays identical.
  const float2 screen{(float(x) + offset.x) * (1.f / float(width)),
      (float(y) + offset.y) / float(height)};
  // The lens point: its own stream, decorrelated from the pixel offset;
  // a camera without a lens ignores it.
  const float2 lens = lensPoint(x, y, camera->hasDepthOfField());
  const float time = camera->rayTime(screen, exposureTime(x, y));
  return camera->generateRay(screen, lens, time, float(width) / float(height));
}

rt::Hit Renderer::traceBeyond(
    const World &world, const Ray &ray, const rt::Hit &previous)
{
  // Step past the previous hit by a relative epsilon so the same surface
  // is not found again, however far from the origin it is.
  const float tMin = previous.t + std::max(1e-4f, previous.t * 1e-5f);
  rt::Hit next;
  world.intersect(ray.origin, ray.direction, tMin, ray.tMax, next, ray.time);
  return next;
}

void Renderer::store(const RenderContext &context,
    FrameBuffers &buffers,
    uint32_t x,
    uint32_t y,
    const PixelSample &sample)
{
  const size_t i = size_t(y) * context.width + x;
  buffers.color[i] = sample.color;
  const FrameBuffers::Needs &needs = buffers.needs;
  if (needs.depth)
    buffers.depth[i] = sample.depth;
  if (needs.normal)
    buffers.normal[i] = sample.normal;
  if (needs.albedo)
    buffers.albedo[i] = sample.albedo;
  if (needs.primitiveId)
    buffers.primitiveId[i] = sample.primitiveId;
  if (needs.objectId)
    buffers.objectId[i] = sample.objectId;
  if (needs.instanceId)
    buffers.instanceId[i] = sample.instanceId;
}

bool Renderer::getProperty(const std::string &name,
    ANARIDataType type,
    void *mem,
    uint64_t size,
    ANARIWaitMask mask)
{
  if (name == "ignoresLights" && type == ANARI_BOOL && mem && size >= 1) {
    *(uint8_t *)mem = ignoresLights() ? 1 : 0;
    return true;
  }
  if (name == "extension" && type == ANARI_STRING_LIST && mem
      && size >= sizeof(const char **)) {
    const char **list = introspection::deviceExtensions();
    std::memcpy(mem, &list, sizeof(list));
    return true;
  }
  return Object::getProperty(name, type, mem, size, mask);
}

} // namespace prism
