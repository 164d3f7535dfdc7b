#include "MovingObject.h"

#include "MotionParameters.h"

namespace prism {

MotionTransform MovingObject::readMotion(unsigned keys)
{
  MotionParameters parameters;
  auto array = [&](const char *name) {
    return (const Array *)readObject(name, {ANARI_ARRAY1D});
  };
  if (keys & kMatrixKeys)
    parameters.transform = array("motion.transform");
  if (keys & kDecomposedKeys) {
    parameters.scale = array("motion.scale");
    parameters.rotation = array("motion.rotation");
    parameters.translation = array("motion.translation");
  }
  parameters.time = read<float2>("time", ANARI_FLOAT32_BOX1, {0.f, 1.f});
  return readMotionTransform(parameters, [&](const std::string &message) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "%s",
        message.c_str());
  });
}

} // namespace prism
