// The full-sphere camera (KHR_CAMERA_OMNIDIRECTIONAL), equirectangular:
// screen x spans 360 degrees of longitude and y 180 degrees of latitude,
// the image centre looks along 'direction' and its top along 'up'.
#pragma once

#include "Camera.h"

namespace prism {

class Omnidirectional : public Camera
{
 public:
  explicit Omnidirectional(DeviceState &device);

 protected:
  void commitParameters() override;
  Ray rayThroughSensor(float2 sensor,
      float eyeShift,
      float2 lensSample,
      float frameAspect) const override;
};

} // namespace prism
