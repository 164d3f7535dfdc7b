#include "Geometry.h"

#include "../object/FormatText.h"

#include "../DeviceInfo.h"
#include "../array/Array.h"
#include "../array/ElementConversion.h"

#include "anari/frontend/type_utility.h"

#include <cmath>
#include <cstdio>
#include <cstring>

namespace prism {
namespace {

// The attributes the base reads, in AttributeData order.
const char *const kAttributeNames[5] = {
    "color", "attribute0", "attribute1", "attribute2", "attribute3"};

const std::initializer_list<ANARIDataType> kColorTypes = {ANARI_UFIXED8,
    ANARI_UFIXED8_VEC2,
    ANARI_UFIXED8_VEC3,
    ANARI_UFIXED8_VEC4,
    ANARI_UFIXED8_R_SRGB,
    ANARI_UFIXED8_RA_SRGB,
    ANARI_UFIXED8_RGB_SRGB,
    ANARI_UFIXED8_RGBA_SRGB,
    ANARI_UFIXED16,
    ANARI_UFIXED16_VEC2,
    ANARI_UFIXED16_VEC3,
    ANARI_UFIXED16_VEC4,
    ANARI_UFIXED32,
    ANARI_UFIXED32_VEC2,
    ANARI_UFIXED32_VEC3,
    ANARI_UFIXED32_VEC4,
    ANARI_FLOAT32,
    ANARI_FLOAT32_VEC2,
    ANARI_FLOAT32_VEC3,
    ANARI_FLOAT32_VEC4};
const std::initializer_list<ANARIDataType> kAttributeTypes = {
    ANARI_FLOAT32, ANARI_FLOAT32_VEC2, ANARI_FLOAT32_VEC3, ANARI_FLOAT32_VEC4};
const std::initializer_list<ANARIDataType> kNormalTypes = {
    ANARI_FIXED16_VEC3, ANARI_FLOAT32_VEC3};
const std::initializer_list<ANARIDataType> kTangentTypes = {ANARI_FIXED16_VEC3,
    ANARI_FIXED16_VEC4,
    ANARI_FLOAT32_VEC3,
    ANARI_FLOAT32_VEC4};

std::vector<float4> toFloat4(const Array *array)
{
  std::vector<float4> out(array ? array->count() : 0);
  if (array) {
    convertToFloat4(array->elementType(),
        array->begin(),
        out.size(),
        array->elementSize(),
        out.data());
  }
  return out;
}

float4 interpolateValues(const std::vector<float4> &values,
    const uint32_t *index,
    const float *weight,
    uint32_t count)
{
  float4 sum{0, 0, 0, 0};
  for (uint32_t i = 0; i < count; i++)
    sum = sum + values[index[i]] * weight[i];
  return sum;
}

} // namespace

Geometry::Geometry(DeviceState &device, const std::string &subtype)
    : Object(device, ANARI_GEOMETRY, subtype)
{}

void Geometry::invalidate(const char *format, ...)
{
  va_list args;
  va_start(args, format);
  const std::string text = formatTextV(format, args);
  va_end(args);
  if (m_valid)
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_ARGUMENT,
        "%s; the geometry will not render",
        text.c_str());
  m_valid = false;
}

void Geometry::commitParameters()
{
  m_valid = true;
  m_primitiveCount = 0;
  m_vertexCount = 0;
  m_positions.clear();
  m_indices.clear();
  m_vertexMotion = VertexMotion();
  readShape();
  readAttributes();
  if (m_valid)
    checkAttributeSizes();
  if (!m_valid)
    m_primitiveCount = 0;
}

const Array *Geometry::readArray(const char *name,
    std::initializer_list<ANARIDataType> elementTypes,
    bool required)
{
  auto *array = (const Array *)readObject(name, {ANARI_ARRAY1D});
  if (!array) {
    if (required)
      invalidate("required parameter '%s' is not set", name);
    return nullptr;
  }
  for (ANARIDataType t : elementTypes) {
    if (array->elementType() == t)
      return array;
  }
  std::string list;
  for (ANARIDataType t : elementTypes)
    list += std::string(list.empty() ? "" : ", ") + anari::toString(t);
  if (required) {
    invalidate("'%s' has element type %s; accepted: %s",
        name,
        anari::toString(array->elementType()),
        list.c_str());
  } else {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'%s' has element type %s and is ignored; accepted: %s",
        name,
        anari::toString(array->elementType()),
        list.c_str());
  }
  return nullptr;
}

bool Geometry::readPositions(size_t minimumCount)
{
  const Array *positions =
      readArray("vertex.position", {ANARI_FLOAT32_VEC3}, true);
  if (!positions)
    return false;
  m_vertexCount = positions->count();
  if (m_vertexCount < minimumCount) {
    invalidate("'vertex.position' has %zu elements; at least %zu are needed",
        m_vertexCount,
        minimumCount);
    return false;
  }
  // Embree reads 16 bytes for each 12-byte vertex: in place where the 4
  // after the last can be read, else a copy with one spare element.
  if (uintptr_t(positions->begin()) % alignof(float) == 0
      && positions->readableAfterEnd(sizeof(float))) {
    m_positions.share((const float3 *)positions->begin(), m_vertexCount);
    return true;
  }
  convertToFloat3(ANARI_FLOAT32_VEC3,
      positions->begin(),
      m_vertexCount,
      positions->elementSize(),
      m_positions.own(m_vertexCount, 1));
  return true;
}

const Array *Geometry::readPositionRadius(size_t minimumCount)
{
  const Array *packed =
      readArray("vertex.positionRadius", {ANARI_FLOAT32_VEC4}, true);
  if (!packed)
    return nullptr;
  for (const char *replaced : {"vertex.position", "vertex.radius", "radius"}) {
    if (isSet(replaced)) {
      readAny(replaced);
      report(ANARI_SEVERITY_WARNING,
          ANARI_STATUS_INVALID_ARGUMENT,
          "'%s' is ignored: 'vertex.positionRadius' is set",
          replaced);
    }
  }
  m_vertexCount = packed->count();
  if (m_vertexCount < minimumCount) {
    invalidate(
        "'vertex.positionRadius' has %zu elements; at least %zu are needed",
        m_vertexCount,
        minimumCount);
    return nullptr;
  }
  return packed;
}

bool Geometry::readDeformablePositions(size_t minimumCount)
{
  const Array *positions = readArray("motion.vertex.position", {ANARI_ARRAY1D});
  const Array *normals = readArray("motion.vertex.normal", {ANARI_ARRAY1D});
  const Array *tangents = readArray("motion.vertex.tangent", {ANARI_ARRAY1D});
  const float2 time = read<float2>("time", ANARI_FLOAT32_BOX1, {0.f, 1.f});
  for (const Array *keys : {positions, normals, tangents}) {
    // Changes to a key array re-commit the geometry, as for any array.
    for (Object *key : keys ? keys->objects() : std::vector<Object *>{})
      dependOn(key);
  }
  if (!positions) {
    if (normals || tangents) {
      report(ANARI_SEVERITY_WARNING,
          ANARI_STATUS_INVALID_ARGUMENT,
          "'motion.vertex.normal' and 'motion.vertex.tangent' are ignored "
          "without 'motion.vertex.position'");
    }
    return readPositions(minimumCount);
  }
  const std::string problem =
      m_vertexMotion.readPositions(*positions, time, minimumCount);
  if (!problem.empty()) {
    if (isSet("vertex.position")) {
      report(ANARI_SEVERITY_WARNING,
          ANARI_STATUS_INVALID_ARGUMENT,
          "%s; using 'vertex.position' (no motion)",
          problem.c_str());
      return readPositions(minimumCount);
    }
    invalidate("%s", problem.c_str());
    return false;
  }
  // The keys take precedence over vertex.position (marked read, unused).
  readAny("vertex.position");
  m_vertexCount = m_vertexMotion.vertexCount();
  m_positions.share(m_vertexMotion.firstPositions().data(), m_vertexCount);
  auto warn = [&](const std::string &message) {
    if (!message.empty()) {
      report(ANARI_SEVERITY_WARNING,
          ANARI_STATUS_INVALID_ARGUMENT,
          "%s; ignored",
          message.c_str());
    }
  };
  if (normals)
    warn(m_vertexMotion.readNormals(*normals, time));
  if (tangents)
    warn(m_vertexMotion.checkTangents(*tangents));
  return true;
}

bool Geometry::readIndices(int components, SharedElements<uint32_t> &indices)
{
  indices.clear();
  const ANARIDataType u32[] = {
      ANARI_UINT32, ANARI_UINT32_VEC2, ANARI_UINT32_VEC3, ANARI_UINT32_VEC4};
  const ANARIDataType u64[] = {
      ANARI_UINT64, ANARI_UINT64_VEC2, ANARI_UINT64_VEC3, ANARI_UINT64_VEC4};
  const Array *array =
      readArray("primitive.index", {u32[components - 1], u64[components - 1]});
  if (!array)
    return false;
  const size_t count = array->count() * size_t(components);
  if (array->elementType() == u64[components - 1]) {
    std::vector<uint64_t> wide(count);
    convertToUint64(array->elementType(),
        array->begin(),
        array->count(),
        array->elementSize(),
        wide.data());
    uint32_t *narrow = indices.own(count);
    for (size_t i = 0; i < count; i++) {
      if (wide[i] > kGeometryMaxIndex) {
        invalidate(
            "'primitive.index' element %zu is %llu, above "
            "geometryMaxIndex",
            i / size_t(components),
            (unsigned long long)wide[i]);
        return true;
      }
      narrow[i] = uint32_t(wide[i]);
    }
  } else if (uintptr_t(array->begin()) % alignof(uint32_t) == 0) {
    indices.share((const uint32_t *)array->begin(), count);
  } else {
    convertToUint32(array->elementType(),
        array->begin(),
        array->count(),
        array->elementSize(),
        indices.own(count));
  }
  return true;
}

void Geometry::generateIndices(SharedElements<uint32_t> &indices, size_t count)
{
  uint32_t *generated = indices.own(count);
  for (size_t i = 0; i < count; i++)
    generated[i] = uint32_t(i);
}

size_t Geometry::copiedBytes() const
{
  return m_positions.copiedBytes() + m_indices.copiedBytes();
}

bool Geometry::getProperty(const std::string &name,
    ANARIDataType type,
    void *mem,
    uint64_t size,
    ANARIWaitMask mask)
{
  if (name == "prism.copiedBytes" && type == ANARI_UINT64 && mem
      && size >= sizeof(uint64_t)) {
    const uint64_t bytes = copiedBytes();
    std::memcpy(mem, &bytes, sizeof(bytes));
    return true;
  }
  return Object::getProperty(name, type, mem, size, mask);
}

void Geometry::requireVertexIndicesBelow(
    size_t vertexCount, const SharedElements<uint32_t> &indices)
{
  for (size_t i = 0; i < indices.size(); i++) {
    if (indices[i] >= vertexCount) {
      invalidate(
          "'primitive.index' refers to vertex %u but there are only %zu "
          "vertices",
          indices[i],
          vertexCount);
      return;
    }
  }
}

std::vector<float> Geometry::readFloats(const char *name)
{
  const Array *array = readArray(name, {ANARI_FLOAT32});
  std::vector<float> out(array ? array->count() : 0);
  if (array) {
    convertToFloat(ANARI_FLOAT32,
        array->begin(),
        out.size(),
        array->elementSize(),
        out.data());
  }
  return out;
}

std::vector<float4> Geometry::readAttributeArray(const std::string &name)
{
  const bool isColor = name.find("color") != std::string::npos;
  return toFloat4(
      readArray(name.c_str(), isColor ? kColorTypes : kAttributeTypes));
}

void Geometry::readAttributes()
{
  const bool faceVarying = faceVaryingCorners() > 0;
  for (int a = 0; a < 5; a++) {
    AttributeData &data = m_attributes[a];
    const std::string name = kAttributeNames[a];
    data.hasUniform = isSet(name.c_str());
    data.uniform = read<float4>(name.c_str(), ANARI_FLOAT32_VEC4, {0, 0, 0, 1});
    data.perPrimitive = readAttributeArray("primitive." + name);
    data.perVertex = readAttributeArray("vertex." + name);
    data.perCorner = faceVarying ? readAttributeArray("faceVarying." + name)
                                 : std::vector<float4>{};
  }
  m_vertexNormals.clear();
  m_cornerNormals.clear();
  m_vertexTangents.clear();
  m_cornerTangents.clear();
  if (faceVarying) {
    auto normals = [&](const char *name) {
      const Array *array = readArray(name, kNormalTypes);
      std::vector<float3> out(array ? array->count() : 0);
      if (array)
        convertToFloat3(array->elementType(),
            array->begin(),
            out.size(),
            array->elementSize(),
            out.data());
      return out;
    };
    m_vertexNormals = normals("vertex.normal");
    m_cornerNormals = normals("faceVarying.normal");
    // Tangents orient normal maps (fourth component: handedness).
    m_vertexTangents = toFloat4(readArray("vertex.tangent", kTangentTypes));
    m_cornerTangents =
        toFloat4(readArray("faceVarying.tangent", kTangentTypes));
  }
}

void Geometry::checkAttributeSizes()
{
  const size_t corners = size_t(faceVaryingCorners()) * m_primitiveCount;
  auto check = [&](const std::string &name, size_t have, size_t need) {
    if (have > 0 && have < need)
      invalidate(
          "'%s' has %zu elements but %zu are needed", name.c_str(), have, need);
  };
  for (int a = 0; a < 5; a++) {
    const AttributeData &data = m_attributes[a];
    const std::string name = kAttributeNames[a];
    check("primitive." + name, data.perPrimitive.size(), m_primitiveCount);
    check("vertex." + name, data.perVertex.size(), m_vertexCount);
    check("faceVarying." + name, data.perCorner.size(), corners);
  }
  check("vertex.normal", m_vertexNormals.size(), m_vertexCount);
  check("faceVarying.normal", m_cornerNormals.size(), corners);
  check("vertex.tangent", m_vertexTangents.size(), m_vertexCount);
  check("faceVarying.tangent", m_cornerTangents.size(), corners);
}

float3 Geometry::surfaceNormal(const rt::Hit &hit, const float3 &) const
{
  return normalize(hit.geometricNormal);
}

float3 Geometry::attributesAt(const rt::Hit &hit,
    const float3 &objectPosition,
    AttributeValues &attributes,
    bool interpolate,
    float time) const
{
  const uint32_t primitive = hit.primitiveId;
  attributes.primitiveId = primitive;
  attributes[Attribute::PrimitiveId] = float4{float(primitive), 0.f, 0.f, 1.f};
  attributes[Attribute::ObjectPosition] =
      float4{objectPosition.x, objectPosition.y, objectPosition.z, 1.f};
  const bool smoothNormals = !m_vertexNormals.empty()
                             || !m_cornerNormals.empty()
                             || m_vertexMotion.hasNormals();
  if (!interpolate && !smoothNormals) {
    // The fast path of renderers that need only the normal.
    const float3 normal = surfaceNormal(hit, objectPosition);
    attributes[Attribute::ObjectNormal] =
        float4{normal.x, normal.y, normal.z, 0.f};
    return normal;
  }
  const Corners corners = cornersAt(primitive, hit.u, hit.v);
  const uint32_t perPrimitive = faceVaryingCorners();
  // Face-varying corner indices follow the spec's formula n * primID + k;
  // the corner order matches cornersAt's vertex order, so corners.weight
  // weighs them too.
  uint32_t cornerIndex[4];
  uint32_t cornerCount = 0;
  if (perPrimitive > 0) {
    cornerCount = corners.count;
    for (uint32_t i = 0; i < corners.count; i++)
      cornerIndex[i] = perPrimitive * primitive + corners.slot[i];
  }
  for (int a = 0; a < 5 && interpolate; a++) {
    const AttributeData &data = m_attributes[a];
    float4 &out = attributes.values[a];
    if (!data.perCorner.empty())
      out = interpolateValues(
          data.perCorner, cornerIndex, corners.weight, cornerCount);
    else if (!data.perVertex.empty())
      out = interpolateValues(
          data.perVertex, corners.vertex, corners.weight, corners.count);
    else if (!data.perPrimitive.empty())
      out = data.perPrimitive[primitive];
    else if (data.hasUniform)
      out = data.uniform;
  }
  float3 smooth{0, 0, 0};
  if (!m_cornerNormals.empty()) {
    for (uint32_t i = 0; i < cornerCount; i++)
      smooth = smooth + m_cornerNormals[cornerIndex[i]] * corners.weight[i];
  } else if (m_vertexMotion.hasNormals()) {
    for (uint32_t i = 0; i < corners.count; i++) {
      smooth =
          smooth
          + m_vertexMotion.normal(corners.vertex[i], time) * corners.weight[i];
    }
  } else if (!m_vertexNormals.empty()) {
    for (uint32_t i = 0; i < corners.count; i++)
      smooth = smooth + m_vertexNormals[corners.vertex[i]] * corners.weight[i];
  }
  // The geometry's own normal only where the interpolated one vanishes.
  const float smoothLength = length(smooth);
  const float3 normal = smoothLength > 0.f ? smooth * (1.f / smoothLength)
                                           : surfaceNormal(hit, objectPosition);
  attributes[Attribute::ObjectNormal] =
      float4{normal.x, normal.y, normal.z, 0.f};
  return normal;
}

bool Geometry::tangentAt(const rt::Hit &hit, float4 &tangent) const
{
  const uint32_t perPrimitive = faceVaryingCorners();
  if (perPrimitive == 0 || !isValid())
    return false;
  const uint32_t primitive = hit.primitiveId;
  const Corners corners = cornersAt(primitive, hit.u, hit.v);
  float4 sum{0, 0, 0, 0};
  if (!m_cornerTangents.empty()) {
    for (uint32_t i = 0; i < corners.count; i++)
      sum = sum
            + m_cornerTangents[perPrimitive * primitive + corners.slot[i]]
                  * corners.weight[i];
  } else if (!m_vertexTangents.empty()) {
    for (uint32_t i = 0; i < corners.count; i++)
      sum = sum + m_vertexTangents[corners.vertex[i]] * corners.weight[i];
  } else {
    return uvTangent(primitive, corners, tangent);
  }
  if (!(lengthSquared(float3{sum.x, sum.y, sum.z}) > 0.f))
    return false;
  tangent = float4{sum.x, sum.y, sum.z, sum.w < 0.f ? -1.f : 1.f};
  return true;
}

bool Geometry::uvTangent(
    uint32_t primitive, const Corners &corners, float4 &tangent) const
{
  // Texture coordinates are attribute0 (the samplers' default input).
  const AttributeData &uv = m_attributes[1];
  if (corners.count < 3 || (uv.perVertex.empty() && uv.perCorner.empty()))
    return false;
  float3 p[3];
  float2 t[3];
  for (int i = 0; i < 3; i++) {
    p[i] = m_positions[corners.vertex[i]];
    const float4 c =
        uv.perCorner.empty()
            ? uv.perVertex[corners.vertex[i]]
            : uv.perCorner[faceVaryingCorners() * primitive + corners.slot[i]];
    t[i] = {c.x, c.y};
  }
  // dp/du of the triangle's linear map from uv to position.
  const float3 e1 = p[1] - p[0], e2 = p[2] - p[0];
  const float du1 = t[1].x - t[0].x, dv1 = t[1].y - t[0].y;
  const float du2 = t[2].x - t[0].x, dv2 = t[2].y - t[0].y;
  const float determinant = du1 * dv2 - du2 * dv1;
  if (!(std::abs(determinant) > 1e-20f))
    return false;
  const float3 dpdu = (e1 * dv2 - e2 * dv1) / determinant;
  const float3 dpdv = (e2 * du1 - e1 * du2) / determinant;
  if (!(lengthSquared(dpdu) > 0.f) || !std::isfinite(dpdu.x + dpdu.y + dpdu.z))
    return false;
  // Handedness: whether (dp/du, dp/dv, Ng) is right-handed.
  const float3 ng = cross(e1, e2);
  const float w = dot(cross(ng, dpdu), dpdv) < 0.f ? -1.f : 1.f;
  tangent = float4{dpdu.x, dpdu.y, dpdu.z, w};
  return true;
}

} // namespace prism
