// ANARIGroup: surfaces, volumes and lights sharing one local space (spec
// 5.6), and the Embree scene of its surfaces (geometry id = surface index).
#pragma once

#include "../object/Object.h"
#include "../rt/Scene.h"
#include "../volume/Volume.h"
#include "Surface.h"

#include <memory>
#include <vector>

namespace prism {

class Group : public Object
{
 public:
  explicit Group(DeviceState &device);

  // Surfaces by Embree geometry id (invalid or invisible ones are NULL).
  const Surface *surface(uint32_t geometryId) const
  {
    return geometryId < m_surfaces.size() ? m_surfaces[geometryId] : nullptr;
  }
  // One more than the largest geometry id.
  uint32_t surfaceCount() const
  {
    return uint32_t(m_surfaces.size());
  }
  // The group's valid, visible volumes.
  const std::vector<const Volume *> &volumes() const
  {
    return m_validVolumes;
  }
  const std::vector<Object *> &lights() const
  {
    return m_lights;
  }
  const rt::Scene &scene() const
  {
    return *m_scene;
  }
  // The bounds of the group's surfaces (volumes() have their own).
  box3 bounds() const
  {
    return m_bounds;
  }
  bool getProperty(const std::string &name,
      ANARIDataType type,
      void *mem,
      uint64_t size,
      ANARIWaitMask mask) override;

  // Takes surfaces and volumes placed directly in a world (the world's
  // implicit group).
  void setSurfaces(const std::vector<Object *> &surfaces);
  void setVolumes(const std::vector<Object *> &volumes);
  void finalize() override;

 protected:
  void commitParameters() override;

 private:
  std::vector<Object *> readObjects(const char *name);

  std::vector<const Surface *> m_surfaces;
  std::vector<Object *> m_volumes;
  std::vector<const Volume *> m_validVolumes;
  std::vector<Object *> m_lights;
  std::unique_ptr<rt::Scene> m_scene;
  box3 m_bounds;
};

} // namespace prism
