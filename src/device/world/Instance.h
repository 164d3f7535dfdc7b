// ANARIInstance: a group placed in the world by one transform or, with
// KHR_INSTANCE_TRANSFORM_ARRAY, by many (spec 5.5). The motion subtypes are
// placed at the shutter's midpoint until motion blur samples time.
#pragma once

#include "../geometry/Attributes.h"
#include "Group.h"

namespace prism {

class Instance : public Object
{
 public:
  Instance(Device &device, const std::string &subtype);

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
  const mat3x4 &worldFromObject(size_t placement) const
  {
    return m_worldFromObject[placement];
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
  void readMotionTransform();
  void readMotionScaleRotationTranslation();
  // Where keys spanning `time` are sampled: the shutter midpoint (0.5).
  float keyPosition(size_t keyCount);

  Group *m_group{nullptr};
  std::vector<mat3x4> m_worldFromObject;
  std::vector<uint32_t> m_ids;
  uint32_t m_id{~0u};
  bool m_hasAttribute[5]{};
  float4 m_attributes[5]{};
};

// The instance of `subtype`, or NULL if the device does not implement it.
Instance *createInstance(Device &device, const std::string &subtype);

} // namespace prism
