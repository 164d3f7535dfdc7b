#include "Cone.h"

#include "../array/Array.h"
#include "../rt/Scene.h"

#include <cmath>

namespace prism {

void Cone::readRadii()
{
  m_vertexRadii = readFloats("vertex.radius");
}

void Cone::checkRadii(size_t segmentCount)
{
  if (!m_vertexRadii.empty() && m_vertexRadii.size() < m_vertexCount)
    invalidate("'vertex.radius' has %zu elements but there are %zu vertices",
        m_vertexRadii.size(),
        m_vertexCount);
  if (!m_segmentRadii.empty() && m_segmentRadii.size() < segmentCount)
    invalidate(
        "'primitive.radius' has %zu elements but there are %zu "
        "primitives",
        m_segmentRadii.size(),
        segmentCount);
}

float Cone::segmentRadius(size_t segment, int end) const
{
  if (!m_segmentRadii.empty())
    return m_segmentRadii[segment];
  if (!m_vertexRadii.empty())
    return m_vertexRadii[m_segments[segment].vertex[end]];
  return m_uniformRadius;
}

void Cone::readShape()
{
  SharedElements<uint32_t> &pairs = m_indices;
  const bool indexed = readIndices(2, pairs);
  const std::string caps = readString("caps", "none");
  const Array *vertexCaps = readArray("vertex.cap", {ANARI_UINT8});
  // Every parameter is read before validation stops early (pull model).
  readRadii();
  if (caps != "none" && caps != "first" && caps != "second" && caps != "both")
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'caps' is '%s'; expected none, first, second or both; using none",
        caps.c_str());
  if (!readPositions(2))
    return;
  if (!indexed) {
    generateIndices(pairs, m_vertexCount / 2 * 2);
  }
  requireVertexIndicesBelow(m_vertexCount, pairs);
  checkRadii(pairs.size() / 2);
  if (vertexCaps && vertexCaps->count() < m_vertexCount)
    invalidate("'vertex.cap' has %zu elements but there are %zu vertices",
        size_t(vertexCaps->count()),
        m_vertexCount);
  if (!isValid())
    return;
  const auto *capFlags =
      vertexCaps ? (const uint8_t *)vertexCaps->begin() : nullptr;
  m_segments.resize(pairs.size() / 2);
  for (size_t i = 0; i < m_segments.size(); i++) {
    Segment &s = m_segments[i];
    s.vertex[0] = pairs[2 * i];
    s.vertex[1] = pairs[2 * i + 1];
    for (int end = 0; end < 2; end++) {
      s.cap[end] = capFlags
                       ? capFlags[s.vertex[end]] != 0
                       : caps == "both"
                             || (end == 0 ? caps == "first" : caps == "second");
    }
  }
  m_indices.clear(); // the segments hold their vertices
  for (size_t i = 0; i < m_segments.size(); i++) {
    m_segments[i].radius[0] = segmentRadius(i, 0);
    m_segments[i].radius[1] = segmentRadius(i, 1);
  }
  setPrimitiveCount(uint32_t(m_segments.size()));
}

void Cone::addTo(rt::Scene &scene, uint32_t id) const
{
  scene.addUser(id, this, primitiveCount());
}

box3 Cone::primitiveBounds(uint32_t primitive) const
{
  const Segment &s = m_segments[primitive];
  box3 b = emptyBox3();
  for (int end = 0; end < 2; end++) {
    const float3 &p = m_positions[s.vertex[end]];
    const float r = std::abs(s.radius[end]);
    b = extend(b, p - float3{r, r, r});
    b = extend(b, p + float3{r, r, r});
  }
  return b;
}

bool Cone::intersectPrimitive(uint32_t primitive,
    const float3 &origin,
    const float3 &direction,
    float tMin,
    float tMax,
    float &tHit,
    float &uHit,
    float &vHit,
    float3 &normalHit,
    uint32_t &) const
{
  const Segment &s = m_segments[primitive];
  const float3 p0 = m_positions[s.vertex[0]];
  const float3 p1 = m_positions[s.vertex[1]];
  const float3 axisVector = p1 - p0;
  const float height = length(axisVector);
  if (height <= 0.f)
    return false;
  const float3 axis = axisVector / height;
  const float r0 = s.radius[0];
  const float slope = (s.radius[1] - r0) / height; // radius change per length

  // Along-axis coordinate s(t) = c + t * dA; radial offset w(t) = wc + t*wd.
  const float3 co = origin - p0;
  const float dA = dot(direction, axis);
  const float cA = dot(co, axis);
  const float3 wd = direction - axis * dA;
  const float3 wc = co - axis * cA;
  const float rc = r0 + slope * cA; // radius at the ray origin's s
  const float a = dot(wd, wd) - slope * slope * dA * dA;
  const float b = 2.f * (dot(wc, wd) - slope * dA * rc);
  const float c = dot(wc, wc) - rc * rc;

  bool found = false;
  float best = tMax;
  auto consider = [&](float t, float along, const float3 &normal) {
    if (t > tMin && t < best) {
      best = t;
      uHit = along / height;
      normalHit = normal;
      found = true;
    }
  };
  const float discriminant = b * b - 4.f * a * c;
  if (std::abs(a) > 1e-12f && discriminant >= 0.f) {
    const float root = std::sqrt(discriminant);
    // The numerically stable pair of roots.
    const float q = -0.5f * (b + std::copysign(root, b));
    const float roots[2] = {q / a, q != 0.f ? c / q : q / a};
    for (float t : roots) {
      const float along = cA + t * dA;
      const float radius = r0 + slope * along;
      if (along < 0.f || along > height || radius < 0.f)
        continue; // outside the segment, or the mirrored nappe
      const float3 radial = wc + wd * t;
      const float radialLength = length(radial);
      if (radialLength <= 0.f)
        continue;
      consider(t, along, radial / radialLength - axis * slope);
    }
  }
  // Flat caps: discs at each end, facing away from the segment.
  if (std::abs(dA) > 1e-12f) {
    for (int end = 0; end < 2; end++) {
      if (!s.cap[end])
        continue;
      const float along = end == 0 ? 0.f : height;
      const float t = (along - cA) / dA;
      const float3 radial = wc + wd * t;
      if (dot(radial, radial) <= s.radius[end] * s.radius[end])
        consider(t, along, end == 0 ? -axis : axis);
    }
  }
  if (found) {
    tHit = best;
    vHit = 0.f;
  }
  return found;
}

Geometry::Corners Cone::cornersAt(uint32_t primitive, float u, float) const
{
  const Segment &s = m_segments[primitive];
  return {2, {s.vertex[0], s.vertex[1]}, {0, 1}, {1.f - u, u}};
}

} // namespace prism
