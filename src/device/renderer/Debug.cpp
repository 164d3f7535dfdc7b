#include "Debug.h"

#include "NormalMapping.h"

#include "SampleHash.h"
#include "VolumeTracing.h"

#include <algorithm>
#include <limits>

namespace prism {
namespace {

// A stable, well-spread color for an id (~0u, "no id", is dark grey).
// Every channel stays at or above 0.25, so no id (0 included) can look like
// a black background.
float3 idColor(uint32_t id)
{
  if (id == ~0u)
    return {0.1f, 0.1f, 0.1f};
  const uint32_t h = mixBits(id + 1u);
  auto channel = [](uint32_t bits) {
    return 0.25f + 0.75f * float(bits & 0xff) / 255.f;
  };
  return {channel(h), channel(h >> 8), channel(h >> 16)};
}

float3 heat(float t)
{
  t = std::clamp(t, 0.f, 1.f);
  return {t, 1.f - std::abs(2.f * t - 1.f), 1.f - t};
}

} // namespace

void Debug::commitParameters()
{
  Renderer::commitParameters();
  const std::string mode = param<std::string>("mode");
  m_attribute = attributeFromName(mode);
  if (mode == "primitiveId")
    m_mode = Mode::PrimitiveId;
  else if (mode == "objectId")
    m_mode = Mode::ObjectId;
  else if (mode == "instanceId")
    m_mode = Mode::InstanceId;
  else if (mode == "Ng")
    m_mode = Mode::GeometricNormal;
  else if (mode == "Ns")
    m_mode = Mode::ShadingNormal;
  else if (mode == "uv")
    m_mode = Mode::Uv;
  else if (mode == "backface")
    m_mode = Mode::Backface;
  else if (mode == "opacityHeatmap")
    m_mode = Mode::OpacityHeatmap;
  else if (m_attribute != Attribute::None)
    m_mode = Mode::Attribute;
  else {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "unknown 'mode' '%s'; using 'Ns'",
        mode.c_str());
    m_mode = Mode::ShadingNormal;
  }
}

PixelSample Debug::shadeSample(const RenderContext &context,
    const Ray &ray,
    const rt::Hit &firstHit,
    uint32_t x,
    uint32_t y) const
{
  PixelSample sample;
  rt::Hit hit = firstHit;
  SurfaceHit surface;
  int layers = 0;
  // Every mode looks at the first surface that is not fully see-through.
  for (; hit.found() && layers < 64; layers++) {
    if (resolveSurfaceHit(*context.world, ray, hit, surface)) {
      const float4 base =
          surface.material().baseColorAndOpacity(surface.attributes);
      if (surface.material().coverage(base.w) >= 1.f)
        break;
      if (m_mode != Mode::OpacityHeatmap
          && surface.material().coverage(base.w) > 0.f)
        break;
    }
    hit = traceBeyond(*context.world, ray, hit);
  }
  // Id views show a volume whose first sample with opacity lies before the
  // surface.
  if ((m_mode == Mode::ObjectId || m_mode == Mode::InstanceId)
      && !context.world->volumes().empty()) {
    MarchSettings firstSample;
    firstSample.stopTransmittance = 1.f; // the first absorbing sample ends it
    const VolumeMarch march = marchVolumes(*context.world,
        ray.origin,
        ray.direction,
        ray.tMin,
        hit.found() ? hit.t : ray.tMax,
        firstSample);
    if (march.firstDepth < std::numeric_limits<float>::infinity()) {
      const float3 c =
          idColor(m_mode == Mode::ObjectId ? march.objectId : march.instanceId);
      sample.color = float4{c.x, c.y, c.z, 1.f};
      sample.depth = march.firstDepth;
      sample.objectId = march.objectId;
      sample.instanceId = march.instanceId;
      return sample;
    }
  }
  if (!hit.found() || !surface.surface) {
    sample.color = m_mode == Mode::OpacityHeatmap && layers > 0
                       ? float4{heat(float(layers) / 8.f).x,
                           heat(float(layers) / 8.f).y,
                           heat(float(layers) / 8.f).z,
                           1.f}
                       : background(context, x, y);
    return sample;
  }
  float3 c{0, 0, 0};
  switch (m_mode) {
  case Mode::PrimitiveId:
    c = idColor(surface.attributes.primitiveId);
    break;
  case Mode::ObjectId:
    c = idColor(surface.surface->id());
    break;
  case Mode::InstanceId:
    c = idColor(surface.placement->instanceId());
    break;
  case Mode::GeometricNormal:
    c = surface.geometricNormal * 0.5f + float3{0.5f, 0.5f, 0.5f};
    break;
  case Mode::ShadingNormal:
    // What shading sees: normal maps included.
    c = shadingNormalWithMap(surface, hit, ray.direction * -1.f) * 0.5f
        + float3{0.5f, 0.5f, 0.5f};
    break;
  case Mode::Uv:
    c = {hit.u, hit.v, 0.f};
    break;
  case Mode::Attribute: {
    const float4 &a = surface.attributes[m_attribute];
    c = {a.x, a.y, a.z};
    break;
  }
  case Mode::Backface:
    c = surface.backFacing ? float3{1, 0, 0} : float3{0, 1, 0};
    break;
  case Mode::OpacityHeatmap:
    c = heat(float(layers) / 8.f);
    break;
  }
  sample.color = float4{c.x, c.y, c.z, 1.f};
  recordSurfaceChannels(sample, hit.t, surface, c);
  return sample;
}

} // namespace prism
