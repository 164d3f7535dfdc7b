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

} // namespace

Instance::Instance(DeviceState &device, const std::string &subtype)
    : MovingObject(device, ANARI_INSTANCE, subtype)
{}

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

  m_motion = MotionTransform();
  if (subtype() == "motionTransform")
    m_motion = readMotion(kMatrixKeys);
  else if (subtype() != "transform")
    m_motion = readMotion(kDecomposedKeys);
  if (m_motion.isSet())
    m_worldFromObject.assign(1, m_motion.at(0.5f));
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
  std::vector<mat3x4> placements = m_worldFromObject;
  if (const MotionTransform *keys = motion()) {
    // Every key and, as rotations bulge between keys, points between them.
    const KeyTimeline &timeline = keys->timeline();
    constexpr uint32_t kBetween = 8;
    for (uint32_t k = 0; k + 1 < timeline.keyCount; k++) {
      for (uint32_t i = 0; i <= kBetween; i++) {
        const float t = float(i) / float(kBetween);
        placements.push_back(keys->at(
            timeline.keyTime(k) * (1.f - t) + timeline.keyTime(k + 1) * t));
      }
    }
  }
  for (const mat3x4 &m : placements) {
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

Instance *createInstance(DeviceState &device, const std::string &subtype)
{
  if (subtype == "transform" || subtype == "motionTransform"
      || subtype == "motionScaleRotationTranslation")
    return new Instance(device, subtype);
  return nullptr;
}

} // namespace prism
