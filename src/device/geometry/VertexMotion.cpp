#include "VertexMotion.h"

#include "../array/Array.h"
#include "../array/ElementConversion.h"

#include "../object/FormatText.h"

#include "anari/frontend/type_utility.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>

namespace prism {
namespace {

// The inner arrays of an array of arrays; a NULL entry or one of another
// element type is named in `problem`.
std::vector<const Array *> keyArrays(const Array &keys,
    const char *name,
    std::initializer_list<ANARIDataType> elementTypes,
    std::string &problem)
{
  std::vector<const Array *> out;
  const std::vector<Object *> objects = keys.objects();
  for (size_t k = 0; k < objects.size(); k++) {
    auto *array = dynamic_cast<const Array *>(objects[k]);
    bool accepted = false;
    for (ANARIDataType t : elementTypes)
      accepted |= array && array->elementType() == t;
    if (!accepted) {
      problem = array ? formatText("'%s' key %zu has element type %s",
                    name,
                    k,
                    anari::toString(array->elementType()))
                      : formatText("'%s' key %zu is not an array", name, k);
      return {};
    }
    out.push_back(array);
  }
  if (out.empty())
    problem = formatText("'%s' has no keys", name);
  return out;
}

KeyTimeline timelineOf(size_t keys, float2 time)
{
  // An empty or reversed span puts every key at its start (no motion).
  const bool span =
      std::isfinite(time.x) && std::isfinite(time.y) && time.x < time.y;
  return {uint32_t(keys), time.x, span ? time.y : time.x};
}

} // namespace

std::string VertexMotion::readPositions(
    const Array &keys, float2 time, size_t minimumCount)
{
  *this = VertexMotion();
  std::string problem;
  const auto arrays =
      keyArrays(keys, "motion.vertex.position", {ANARI_FLOAT32_VEC3}, problem);
  if (!problem.empty())
    return problem;
  const size_t count = arrays[0]->count();
  if (count < minimumCount) {
    return formatText(
        "'motion.vertex.position' keys have %zu vertices; at least %zu are "
        "needed",
        count,
        minimumCount);
  }
  for (size_t k = 1; k < arrays.size(); k++) {
    if (arrays[k]->count() != count) {
      return formatText(
          "'motion.vertex.position' key %zu has %llu vertices but key 0 has "
          "%zu",
          k,
          (unsigned long long)arrays[k]->count(),
          count);
    }
  }
  if (!(std::isfinite(time.x) && std::isfinite(time.y) && time.x <= time.y))
    return formatText("'time' [%g, %g] is not an interval", time.x, time.y);
  m_vertexCount = count;
  for (const Array *array : arrays) {
    // One extra element: Embree reads 16 bytes for each 12-byte vertex.
    std::vector<float3> positions(count + 1);
    convertToFloat3(ANARI_FLOAT32_VEC3,
        array->begin(),
        count,
        array->elementSize(),
        positions.data());
    m_positions.push_back(std::move(positions));
  }
  m_positionTimeline = timelineOf(arrays.size(), time);
  return {};
}

std::string VertexMotion::readNormals(const Array &keys, float2 time)
{
  m_normals.clear();
  std::string problem;
  const auto arrays = keyArrays(keys,
      "motion.vertex.normal",
      {ANARI_FLOAT32_VEC3, ANARI_FIXED16_VEC3},
      problem);
  if (!problem.empty())
    return problem;
  for (size_t k = 0; k < arrays.size(); k++) {
    if (arrays[k]->count() < m_vertexCount) {
      return formatText(
          "'motion.vertex.normal' key %zu has %llu normals for %zu vertices",
          k,
          (unsigned long long)arrays[k]->count(),
          m_vertexCount);
    }
  }
  for (const Array *array : arrays) {
    std::vector<float3> normals(m_vertexCount);
    convertToFloat3(array->elementType(),
        array->begin(),
        m_vertexCount,
        array->elementSize(),
        normals.data());
    m_normals.push_back(std::move(normals));
  }
  m_normalTimeline = timelineOf(arrays.size(), time);
  return {};
}

std::string VertexMotion::checkTangents(const Array &keys) const
{
  std::string problem;
  const auto arrays = keyArrays(keys,
      "motion.vertex.tangent",
      {ANARI_FLOAT32_VEC3,
          ANARI_FIXED16_VEC3,
          ANARI_FLOAT32_VEC4,
          ANARI_FIXED16_VEC4},
      problem);
  for (size_t k = 0; k < arrays.size() && problem.empty(); k++) {
    if (arrays[k]->count() < m_vertexCount) {
      problem = formatText(
          "'motion.vertex.tangent' key %zu has %llu tangents for %zu vertices",
          k,
          (unsigned long long)arrays[k]->count(),
          m_vertexCount);
    }
  }
  return problem;
}

rt::VertexKeys VertexMotion::positionKeys() const
{
  rt::VertexKeys keys;
  for (const std::vector<float3> &positions : m_positions)
    keys.positions.push_back(positions.data());
  keys.timeline = m_positionTimeline;
  return keys;
}

float3 VertexMotion::normal(uint32_t vertex, float time) const
{
  if (m_normals.size() == 1)
    return m_normals[0][vertex];
  const KeyTimeline::Position at = m_normalTimeline.locate(time);
  return m_normals[at.index][vertex] * (1.f - at.fraction)
         + m_normals[at.index + 1][vertex] * at.fraction;
}

} // namespace prism
