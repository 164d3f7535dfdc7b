// ANARISurface: a geometry paired with a material (spec 5.8).
#pragma once

#include "../geometry/Geometry.h"
#include "../material/Material.h"

namespace prism {

class Surface : public Object
{
 public:
  explicit Surface(DeviceState &device) : Object(device, ANARI_SURFACE, "") {}

  const Geometry *geometry() const
  {
    return m_geometry;
  }
  const Material *material() const
  {
    return m_material;
  }
  bool visible() const
  {
    return m_visible;
  }
  // KHR_FRAME_CHANNEL_OBJECT_ID: the user's id, ~0u when unset.
  uint32_t id() const
  {
    return m_id;
  }
  bool isValid() const override
  {
    return m_geometry && m_material && m_geometry->isValid()
           && m_material->isValid();
  }

 protected:
  void commitParameters() override
  {
    // dynamic_cast: objects of unknown subtypes are inert, not geometry.
    m_geometry =
        dynamic_cast<Geometry *>(readObject("geometry", {ANARI_GEOMETRY}));
    m_material =
        dynamic_cast<Material *>(readObject("material", {ANARI_MATERIAL}));
    m_visible = readBool("visible", true);
    m_id = read<uint32_t>("id", ANARI_UINT32, ~0u);
  }

 private:
  Geometry *m_geometry{nullptr};
  Material *m_material{nullptr};
  bool m_visible{true};
  uint32_t m_id{~0u};
};

} // namespace prism
