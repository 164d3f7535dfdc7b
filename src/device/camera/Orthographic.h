// The parallel-projection camera (KHR_CAMERA_ORTHOGRAPHIC).
#pragma once

#include "Camera.h"

namespace prism {

class Orthographic : public Camera
{
 public:
  explicit Orthographic(DeviceState &device);

 protected:
  void commitParameters() override;
  Ray rayThroughSensor(float2 sensor,
      float eyeShift,
      float2 lensSample,
      float frameAspect) const override;

 private:
  float m_height{1.f}; // world-space height of the image
  float m_near{0.f};
  float m_far{std::numeric_limits<float>::infinity()};
};

} // namespace prism
