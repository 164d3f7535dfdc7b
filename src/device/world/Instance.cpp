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
  m_transforms = nullptr;
  m_transformCount = 0;
  m_ids = nullptr;
  for (int a = 0; a < 5; a++) {
    m_hasAttribute[a] = isSet(kAttributeNames[a]);
    m_attributes[a] =
        read<float4>(kAttributeNames[a], ANARI_FLOAT32_VEC4, {0, 0, 0, 1});
  }

  size_t idCount = 0;
  const Parameter *ids = readAny("id");
  if (ids && ids->type() == ANARI_UINT32) {
    m_id = ids->as<uint32_t>();
  } else if (ids && ids->type() == ANARI_ARRAY1D
             && ((const Array *)ids->object())->elementType() == ANARI_UINT32) {
    auto *array = (const Array *)ids->object();
    dependOn(ids->object());
    m_ids = (const unsigned char *)array->begin();
    idCount = array->count();
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
    } else if (array->count() > 0) {
      m_transforms = (const unsigned char *)array->begin();
      m_transformCount = array->count();
    }
  } else if (transform) {
    wrongType("transform", transform->type(), {ANARI_FLOAT32_MAT4});
  }

  m_motion = MotionTransform();
  if (subtype() == "motionTransform")
    m_motion = readMotion(kMatrixKeys);
  else if (subtype() != "transform")
    m_motion = readMotion(kDecomposedKeys);
  m_single = single;
  if (m_motion.isSet()) {
    m_transforms = nullptr;
    m_single = m_motion.at(0.5f);
  }
  if (m_ids && idCount < placementCount()) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'id' array has %zu elements for %zu transforms; ids are ignored",
        idCount,
        placementCount());
    m_ids = nullptr;
  }
}

mat3x4 Instance::worldFromObject(size_t placement) const
{
  if (!m_transforms)
    return m_single;
  // An application's memory need not be aligned for mat4.
  mat4 m;
  std::memcpy(&m, m_transforms + placement * sizeof(mat4), sizeof(mat4));
  return affinePart(m);
}

uint32_t Instance::id(size_t placement) const
{
  if (!m_ids)
    return m_id;
  uint32_t id;
  std::memcpy(&id, m_ids + placement * sizeof(uint32_t), sizeof(id));
  return id;
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
  auto add = [&](const mat3x4 &m) {
    for (int corner = 0; corner < 8; corner++) {
      const float3 p{corner & 1 ? local.upper.x : local.lower.x,
          corner & 2 ? local.upper.y : local.lower.y,
          corner & 4 ? local.upper.z : local.lower.z};
      out = extend(out, transformPoint(m, p));
    }
  };
  for (size_t i = 0; i < placementCount(); i++)
    add(worldFromObject(i));
  if (const MotionTransform *keys = motion()) {
    // Every key and, as rotations bulge between keys, points between them.
    const KeyTimeline &timeline = keys->timeline();
    constexpr uint32_t kBetween = 8;
    for (uint32_t k = 0; k + 1 < timeline.keyCount; k++) {
      for (uint32_t i = 0; i <= kBetween; i++) {
        const float t = float(i) / float(kBetween);
        add(keys->at(
            timeline.keyTime(k) * (1.f - t) + timeline.keyTime(k + 1) * t));
      }
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
