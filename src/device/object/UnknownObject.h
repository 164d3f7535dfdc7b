// Objects of a subtype the device does not implement: they accept
// parameters (reported once, at creation) and never render.
#pragma once

#include "Object.h"

namespace prism {

class UnknownObject : public Object
{
 public:
  using Object::Object;
  bool isValid() const override
  {
    return false;
  }

 protected:
  void commitParameters() override
  {
    // Read everything: the subtype was already reported as unknown, so its
    // parameters are not reported again one by one.
    readAll();
  }
};

} // namespace prism
