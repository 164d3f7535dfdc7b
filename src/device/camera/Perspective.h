// The thin-lens perspective camera (KHR_CAMERA_PERSPECTIVE); a pinhole when
// apertureRadius is 0.
#pragma once

#include "Camera.h"

namespace prism {

class Perspective : public Camera
{
 public:
  explicit Perspective(DeviceState &device);

 public:
  bool pinhole(Pinhole &out, float frameAspect) const override;

 protected:
  void commitParameters() override;
  Ray rayThroughSensor(float2 sensor,
      float eyeShift,
      float2 lensSample,
      float frameAspect) const override;

 private:
  float m_halfHeight{0.57735f}; // tan(fovy / 2) at unit distance
  float m_near{0.f};
  float m_far{std::numeric_limits<float>::infinity()};
};

} // namespace prism
