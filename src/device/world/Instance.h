// ANARIInstance: a group placed in the world by one transform or, with
// KHR_INSTANCE_TRANSFORM_ARRAY, by many (spec 5.5), or moving over the
// shutter by transform keys (the motionTransform and
// motionScaleRotationTranslation subtypes).
#pragma once

#include "../array/MovingObject.h"
#include "../geometry/Attributes.h"
#include "../math/MotionTransform.h"
#include "Group.h"

namespace prism {

class Instance : public MovingObject
{
 public:
  Instance(DeviceState &device, const std::string &subtype);

  bool isValid() const override
  {
    return m_group != nullptr;
  }
  const Group *group() const
  {
    return m_group;
  }
  // How many placements of the group (1, or the transform array's size).
  size_t placementCount() const
  {
    return m_transforms ? m_transformCount : 1;
  }
  // At the shutter midpoint (time 0.5) for a moving instance. A transform
  // array is read where it lies (ten million instances would otherwise
  // hold a second copy of every transform).
  mat3x4 worldFromObject(size_t placement) const;
  // The transform keys of a moving instance (one placement), or NULL.
  const MotionTransform *motion() const
  {
    return m_motion.isMoving() ? &m_motion : nullptr;
  }
  uint32_t id(size_t placement) const;
  // Sets the instance's uniform attributes (beneath the geometry's own).
  void applyAttributes(AttributeValues &attributes) const;
  box3 bounds() const;

  bool getProperty(const std::string &name,
      ANARIDataType type,
      void *mem,
      uint64_t size,
      ANARIWaitMask mask) override;

 protected:
  void commitParameters() override;

 private:
  Group *m_group{nullptr};
  // The transform array's FLOAT32_MAT4 elements in place, or NULL: then
  // the one placement is m_single.
  const unsigned char *m_transforms{nullptr};
  size_t m_transformCount{0};
  mat3x4 m_single{kIdentityMat3x4};
  MotionTransform m_motion;
  const unsigned char *m_ids{nullptr}; // the id array's UINT32s in place
  uint32_t m_id{~0u};
  bool m_hasAttribute[5]{};
  float4 m_attributes[5]{};
};

// The instance of `subtype`, or NULL if the device does not implement it.
Instance *createInstance(DeviceState &device, const std::string &subtype);

} // namespace prism
