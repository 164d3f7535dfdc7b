#include "Isosurface.h"

#include "../array/Array.h"
#include "../rt/Scene.h"
#include "../volume/SpatialField.h"

#include <algorithm>
#include <cmath>

namespace prism {
namespace {

// Blocks are this many cells wide: small enough that few blocks without a
// surface get marched, large enough that Embree's tree stays small.
constexpr float kCellsPerBlock = 4.f;
// At most this many blocks (wider blocks for very fine fields).
constexpr double kMaxBlocks = 1 << 21;
// Marching steps per cell: crossings closer together than this are missed.
constexpr float kStepsPerCell = 4.f;
// Crossings are refined to this fraction of a cell.
constexpr float kRefinement = 1e-6f;

// The part [t0, t1] of the ray inside `box`, or false.
bool clipToBox(const box3 &box,
    const float3 &origin,
    const float3 &direction,
    float &t0,
    float &t1)
{
  for (int axis = 0; axis < 3; axis++) {
    const float inverse = 1.f / direction[axis];
    float near = (box.lower[axis] - origin[axis]) * inverse;
    float far = (box.upper[axis] - origin[axis]) * inverse;
    if (near > far)
      std::swap(near, far);
    // NaN (a ray in the slab's plane) leaves the interval as it is.
    t0 = near > t0 ? near : t0;
    t1 = far < t1 ? far : t1;
  }
  return t0 <= t1;
}

} // namespace

void Isosurface::readShape()
{
  m_field = nullptr;
  m_isovalues.clear();
  m_blocks.clear();
  Object *field = readObject("field", {ANARI_SPATIAL_FIELD});
  const bool haveIsovalues = readIsovalues();
  if (!field) {
    invalidate("required parameter 'field' is not set");
    return;
  }
  // Unknown field subtypes are inert objects, not SpatialFields.
  m_field = dynamic_cast<const SpatialField *>(field);
  if (!m_field || !m_field->isValid()) {
    invalidate(
        "'field' (%s) is not a valid spatial field", field->describe().c_str());
    m_field = nullptr;
    return;
  }
  if (!haveIsovalues)
    return;
  setPrimitiveCount(uint32_t(m_isovalues.size()));
  buildBlocks();
}

bool Isosurface::readIsovalues()
{
  const Parameter *isovalue = readAny("isovalue");
  if (!isovalue) {
    invalidate("required parameter 'isovalue' is not set");
    return false;
  }
  if (isovalue->type() == ANARI_FLOAT32) {
    m_isovalues = {isovalue->as<float>()};
    return true;
  }
  if (isovalue->type() != ANARI_ARRAY1D) {
    wrongType("isovalue", isovalue->type(), {ANARI_FLOAT32, ANARI_ARRAY1D});
    invalidate("'isovalue' is neither FLOAT32 nor ARRAY1D of FLOAT32");
    return false;
  }
  const Array *values = readArray("isovalue", {ANARI_FLOAT32}, true);
  if (!values)
    return false;
  const auto *first = (const float *)values->begin();
  m_isovalues.assign(first, first + values->count());
  if (m_isovalues.empty()) {
    invalidate("'isovalue' is empty");
    return false;
  }
  return true;
}

void Isosurface::buildBlocks()
{
  const box3 bounds = m_field->bounds();
  const float cellSize = m_field->cellSize();
  if (isEmpty(bounds) || !(cellSize > 0.f) || !std::isfinite(cellSize))
    return;
  const float3 size = extent(bounds);
  if (!std::isfinite(size.x + size.y + size.z))
    return; // a mesh spanning more than floats hold: nothing to march
  m_step = cellSize / kStepsPerCell;
  float width = kCellsPerBlock * cellSize;
  auto blocksAlong = [&](float length) {
    return std::max(1.0, std::ceil(double(length) / width));
  };
  const double total =
      blocksAlong(size.x) * blocksAlong(size.y) * blocksAlong(size.z);
  if (total > kMaxBlocks)
    width *= float(std::cbrt(total / kMaxBlocks)) * 1.01f;
  const int count[3] = {int(blocksAlong(size.x)),
      int(blocksAlong(size.y)),
      int(blocksAlong(size.z))};
  for (int z = 0; z < count[2]; z++) {
    for (int y = 0; y < count[1]; y++) {
      for (int x = 0; x < count[0]; x++) {
        const float3 lower =
            bounds.lower + width * float3{float(x), float(y), float(z)};
        const box3 block{
            lower, min(lower + float3{width, width, width}, bounds.upper)};
        float lo, hi;
        m_field->valueRange(block, lo, hi);
        const bool holdsSurface = std::any_of(m_isovalues.begin(),
            m_isovalues.end(),
            [&](float iso) { return iso >= lo && iso <= hi; });
        if (holdsSurface)
          m_blocks.push_back(block);
      }
    }
  }
}

void Isosurface::addTo(rt::Scene &scene, uint32_t id) const
{
  scene.addUser(id, this, m_blocks.size());
}

box3 Isosurface::primitiveBounds(uint32_t block) const
{
  return m_blocks[block];
}

float Isosurface::refineCrossing(const float3 &origin,
    const float3 &direction,
    float ta,
    float tb,
    float isovalue) const
{
  float ga = m_field->sample(origin + ta * direction) - isovalue;
  float gb = m_field->sample(origin + tb * direction) - isovalue;
  const float tolerance = kRefinement * m_field->cellSize() / length(direction);
  for (int i = 0; i < 64 && tb - ta > tolerance; i++) {
    const float tm = 0.5f * (ta + tb);
    if (tm <= ta || tm >= tb)
      break; // as fine as floats go
    const float gm = m_field->sample(origin + tm * direction) - isovalue;
    if (std::isnan(gm))
      break;
    if ((gm < 0.f) == (ga < 0.f)) {
      ta = tm;
      ga = gm;
    } else {
      tb = tm;
      gb = gm;
    }
  }
  // The root of the line through the final bracket.
  const float w = ga / (ga - gb);
  return std::isfinite(w) ? ta + std::clamp(w, 0.f, 1.f) * (tb - ta) : tb;
}

bool Isosurface::intersectPrimitive(uint32_t block,
    const float3 &origin,
    const float3 &direction,
    float tMin,
    float tMax,
    float &tHit,
    float &uHit,
    float &vHit,
    float3 &normalHit,
    uint32_t &isovalueIndex) const
{
  float t0 = tMin, t1 = tMax;
  if (!clipToBox(m_blocks[block], origin, direction, t0, t1))
    return false;
  const float dt = m_step / length(direction);
  if (!(dt > 0.f) || !std::isfinite(dt))
    return false;
  float ta = t0;
  float fa = m_field->sample(origin + ta * direction);
  while (ta < t1) {
    const float tb = std::min(ta + dt, t1);
    const float fb = m_field->sample(origin + tb * direction);
    // NaN on either side: outside the field, no surface there.
    if (!std::isnan(fa) && !std::isnan(fb)) {
      bool found = false;
      float nearest = tb;
      for (size_t i = 0; i < m_isovalues.size(); i++) {
        const float iso = m_isovalues[i];
        if ((fa < iso) == (fb < iso))
          continue;
        const float t = refineCrossing(origin, direction, ta, tb, iso);
        if (t > tMin && t < tMax && (!found || t < nearest)) {
          found = true;
          nearest = t;
          isovalueIndex = uint32_t(i);
        }
      }
      if (found) {
        tHit = nearest;
        uHit = vHit = 0.f;
        normalHit = m_field->gradient(origin + nearest * direction);
        if (!std::isfinite(normalHit.x + normalHit.y + normalHit.z)
            || lengthSquared(normalHit) == 0.f)
          normalHit = -1.f * direction; // flat field: face the ray
        return true;
      }
    }
    if (tb <= ta)
      break; // a step too small to move t
    ta = tb;
    fa = fb;
  }
  return false;
}

float3 Isosurface::surfaceNormal(
    const rt::Hit &hit, const float3 &objectPosition) const
{
  const float3 gradient =
      m_field ? m_field->gradient(objectPosition) : float3{0, 0, 0};
  if (std::isfinite(gradient.x + gradient.y + gradient.z)
      && lengthSquared(gradient) > 0.f)
    return normalize(gradient);
  return normalize(hit.geometricNormal);
}

} // namespace prism
