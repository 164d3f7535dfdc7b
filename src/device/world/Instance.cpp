#include "Instance.h"

#include "../array/Array.h"
#include "../array/ElementConversion.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace prism {
namespace {

const char *const kAttributeNames[5] = {
    "color", "attribute0", "attribute1", "attribute2", "attribute3"};

mat3x4 affinePart(const mat4 &m)
{
  return {{{m.col[0].x, m.col[0].y, m.col[0].z},
      {m.col[1].x, m.col[1].y, m.col[1].z},
      {m.col[2].x, m.col[2].y, m.col[2].z},
      {m.col[3].x, m.col[3].y, m.col[3].z}}};
}

mat3x4 lerp(const mat3x4 &a, const mat3x4 &b, float t)
{
  mat3x4 out;
  for (int c = 0; c < 4; c++)
    out.col[c] = a.col[c] * (1.f - t) + b.col[c] * t;
  return out;
}

// Rotation matrix of a unit quaternion (i, j, k, w).
mat3x4 rotation(float4 q)
{
  const float x = q.x, y = q.y, z = q.z, w = q.w;
  return {{{1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w)},
      {2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w)},
      {2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y)},
      {0, 0, 0}}};
}

float4 slerp(float4 a, float4 b, float t)
{
  float cosine = dot(a, b);
  if (cosine < 0.f) { // the shorter way round
    b = b * -1.f;
    cosine = -cosine;
  }
  if (cosine > 0.9995f)
    return normalize(a * (1.f - t) + b * t);
  const float angle = std::acos(cosine);
  return (a * std::sin((1.f - t) * angle) + b * std::sin(t * angle))
         / std::sin(angle);
}

} // namespace

Instance::Instance(Device &device, const std::string &subtype)
    : Object(device, ANARI_INSTANCE, subtype)
{}

float Instance::keyPosition(size_t keyCount)
{
  struct Box1
  {
    float lower, upper;
  };
  const auto time = read<Box1>("time", ANARI_FLOAT32_BOX1, {0.f, 1.f});
  const float span = time.upper - time.lower;
  const float at = span > 0.f ? (0.5f - time.lower) / span : 0.f;
  return std::clamp(at, 0.f, 1.f) * float(keyCount - 1);
}

void Instance::commitParameters()
{
  m_group = dynamic_cast<Group *>(readObject("group", {ANARI_GROUP}));
  if (!m_group && isSet("group") == false)
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "required parameter 'group' is not set; the instance is empty");
  m_worldFromObject.clear();
  m_ids.clear();
  for (int a = 0; a < 5; a++) {
    m_hasAttribute[a] = isSet(kAttributeNames[a]);
    m_attributes[a] =
        read<float4>(kAttributeNames[a], ANARI_FLOAT32_VEC4, {0, 0, 0, 1});
  }

  const Parameter *ids = readAny("id");
  if (ids && ids->type() == ANARI_UINT32) {
    m_id = ids->as<uint32_t>();
  } else if (ids && ids->type() == ANARI_ARRAY1D
             && ((const Array *)ids->object())->elementType() == ANARI_UINT32) {
    auto *array = (const Array *)ids->object();
    dependOn(ids->object());
    m_ids.assign((const uint32_t *)array->begin(),
        (const uint32_t *)array->begin() + array->count());
    m_id = ~0u;
  } else {
    if (ids)
      wrongType("id", ids->type(), {ANARI_UINT32, ANARI_ARRAY1D});
    m_id = ~0u;
  }

  const Parameter *transform = readAny("transform");
  mat3x4 single = kIdentityMat3x4;
  if (transform && transform->type() == ANARI_FLOAT32_MAT4) {
    single = affinePart(transform->as<mat4>());
  } else if (transform && transform->type() == ANARI_ARRAY1D
             && subtype() == "transform") {
    auto *array = (const Array *)transform->object();
    dependOn(transform->object());
    if (array->elementType() != ANARI_FLOAT32_MAT4) {
      wrongType("transform", transform->type(), {ANARI_FLOAT32_MAT4});
    } else {
      const auto *matrices = (const mat4 *)array->begin();
      for (uint64_t i = 0; i < array->count(); i++)
        m_worldFromObject.push_back(affinePart(matrices[i]));
    }
  } else if (transform) {
    wrongType("transform", transform->type(), {ANARI_FLOAT32_MAT4});
  }

  if (subtype() == "motionTransform")
    readMotionTransform();
  else if (subtype() == "motionScaleRotationTranslation")
    readMotionScaleRotationTranslation();
  if (m_worldFromObject.empty())
    m_worldFromObject.push_back(single);

  if (!m_ids.empty() && m_ids.size() < m_worldFromObject.size()) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'id' array has %zu elements for %zu transforms; ids are ignored",
        m_ids.size(),
        m_worldFromObject.size());
    m_ids.clear();
  }
}

void Instance::readMotionTransform()
{
  auto *keys = (const Array *)readObject("motion.transform", {ANARI_ARRAY1D});
  if (!keys || keys->elementType() != ANARI_FLOAT32_MAT4 || keys->count() == 0)
    return;
  const auto *matrices = (const mat4 *)keys->begin();
  const float at = keyPosition(keys->count());
  const size_t i = std::min(size_t(at), size_t(keys->count() - 1));
  const size_t j = std::min(i + 1, size_t(keys->count() - 1));
  m_worldFromObject.push_back(
      lerp(affinePart(matrices[i]), affinePart(matrices[j]), at - float(i)));
}

void Instance::readMotionScaleRotationTranslation()
{
  auto keysOf = [&](const char *name, ANARIDataType type) {
    auto *array = (const Array *)readObject(name, {ANARI_ARRAY1D});
    return array && array->elementType() == type && array->count() > 0
               ? array
               : nullptr;
  };
  const Array *scale = keysOf("motion.scale", ANARI_FLOAT32_VEC3);
  const Array *rotate = keysOf("motion.rotation", ANARI_FLOAT32_QUAT_IJKW);
  const Array *translate = keysOf("motion.translation", ANARI_FLOAT32_VEC3);
  const size_t keys = std::max({scale ? scale->count() : 0,
      rotate ? rotate->count() : 0,
      translate ? translate->count() : 0});
  if (keys == 0)
    return;
  const float at = keyPosition(keys);
  auto sample3 = [&](const Array *a, float3 fallback) {
    if (!a)
      return fallback;
    const auto *v = (const float3 *)a->begin();
    const float local =
        at * float(a->count() - 1) / float(std::max<size_t>(keys - 1, 1));
    const size_t i = std::min(size_t(local), size_t(a->count() - 1));
    const size_t j = std::min(i + 1, size_t(a->count() - 1));
    return v[i] * (1.f - (local - float(i))) + v[j] * (local - float(i));
  };
  float4 q{0, 0, 0, 1};
  if (rotate) {
    const auto *v = (const float4 *)rotate->begin();
    const float local =
        at * float(rotate->count() - 1) / float(std::max<size_t>(keys - 1, 1));
    const size_t i = std::min(size_t(local), size_t(rotate->count() - 1));
    const size_t j = std::min(i + 1, size_t(rotate->count() - 1));
    q = slerp(normalize(v[i]), normalize(v[j]), local - float(i));
  }
  const float3 s = sample3(scale, {1, 1, 1});
  const float3 t = sample3(translate, {0, 0, 0});
  // Scale first, then rotate, then translate (spec 5.5.3).
  mat3x4 m = rotation(q);
  m.col[0] = m.col[0] * s.x;
  m.col[1] = m.col[1] * s.y;
  m.col[2] = m.col[2] * s.z;
  m.col[3] = t;
  m_worldFromObject.push_back(m);
}

void Instance::applyAttributes(AttributeValues &attributes) const
{
  for (int a = 0; a < 5; a++) {
    if (m_hasAttribute[a])
      attributes.values[a] = m_attributes[a];
  }
}

box3 Instance::bounds() const
{
  box3 out = emptyBox3();
  if (!m_group || isEmpty(m_group->bounds()))
    return out;
  const box3 local = m_group->bounds();
  for (const mat3x4 &m : m_worldFromObject) {
    for (int corner = 0; corner < 8; corner++) {
      const float3 p{corner & 1 ? local.upper.x : local.lower.x,
          corner & 2 ? local.upper.y : local.lower.y,
          corner & 4 ? local.upper.z : local.lower.z};
      out = extend(out, transformPoint(m, p));
    }
  }
  return out;
}

bool Instance::getProperty(const std::string &name,
    ANARIDataType type,
    void *mem,
    uint64_t size,
    ANARIWaitMask mask)
{
  const box3 b = bounds();
  if (name == "bounds" && type == ANARI_FLOAT32_BOX3 && mem
      && size >= sizeof(box3) && !isEmpty(b)) {
    std::memcpy(mem, &b, sizeof(b));
    return true;
  }
  return Object::getProperty(name, type, mem, size, mask);
}

Instance *createInstance(Device &device, const std::string &subtype)
{
  if (subtype == "transform" || subtype == "motionTransform"
      || subtype == "motionScaleRotationTranslation")
    return new Instance(device, subtype);
  return nullptr;
}

} // namespace prism
