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
    return m_group && !m_worldFromObject.empty();
  }
  const Group *group() const
  {
    return m_group;
  }
  // How many placements of the group (1, or the transform array's size).
  size_t placementCount() const
  {
    return m_worldFromObject.size();
  }
  // At the shutter midpoint (time 0.5) for a moving instance.
  const mat3x4 &worldFromObject(size_t placement) const
  {
    return m_worldFromObject[placement];
  }
  // The transform keys of a moving instance (one placement), or NULL.
  const MotionTransform *motion() const
  {
    return m_motion.isMoving() ? &m_motion : nullptr;
  }
  uint32_t id(size_t placement) const
  {
    return m_ids.empty() ? m_id : m_ids[placement];
  }
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
  std::vector<mat3x4> m_worldFromObject;
  MotionTransform m_motion;
  std::vector<uint32_t> m_ids;
  uint32_t m_id{~0u};
  bool m_hasAttribute[5]{};
  float4 m_attributes[5]{};
};

// The instance of `subtype`, or NULL if the device does not implement it.
Instance *createInstance(DeviceState &device, const std::string &subtype);

} // namespace prism
