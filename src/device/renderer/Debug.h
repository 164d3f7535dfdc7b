// A renderer for looking at data rather than light: one primary ray per
// pixel, colored by `mode` (documented in docs/renderers.md):
//   primitiveId, objectId, instanceId  ids as distinct hashed colors
//   Ng, Ns                             geometric / shading normal, n*0.5+0.5
//   uv                                 the primitive's hit coordinates
//   attribute0..3, color               the attribute's value at the hit
//   backface                           green front faces, red back faces
//   opacityHeatmap                     see-through layers crossed, blue to red
#pragma once

#include "Renderer.h"

namespace prism {

class Debug : public Renderer
{
 public:
  enum class Mode {
    PrimitiveId,
    ObjectId,
    InstanceId,
    GeometricNormal,
    ShadingNormal,
    Uv,
    Attribute, // m_attribute says which
    Backface,
    OpacityHeatmap,
  };

  explicit Debug(DeviceState &device) : Renderer(device, "debug") {}

  bool ignoresLights() const override
  {
    return true; // false colors
  }

 protected:
  void commitParameters() override;
  PixelSample shadeSample(const RenderContext &context,
      const Ray &ray,
      const rt::Hit &hit,
      uint32_t x,
      uint32_t y) const override;

 private:
  Mode m_mode{Mode::ShadingNormal};
  Attribute m_attribute{Attribute::Color};
};

} // namespace prism
