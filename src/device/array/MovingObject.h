// An object whose placement may move over its `time` box: cameras and
// instances read the same motion.* parameters through it.
#pragma once

#include "../math/MotionTransform.h"
#include "../object/Object.h"

namespace prism {

class MovingObject : public Object
{
 public:
  using Object::Object;

 protected:
  // Which key arrays a subtype accepts.
  enum MotionKeys : unsigned {
    kMatrixKeys = 1,     // motion.transform
    kDecomposedKeys = 2, // motion.scale, motion.rotation, motion.translation
  };
  // The keys of the committed motion.* arrays of the kinds in `keys`,
  // spread over `time`; unusable input is warned about and dropped.
  MotionTransform readMotion(unsigned keys);
};

} // namespace prism
