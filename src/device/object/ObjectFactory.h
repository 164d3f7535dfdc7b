// Creates the object behind anariNew*: one `if` chain per category, so
// every subtype the device implements is listed in one place.
#pragma once

#include "Object.h"

namespace prism {

// A new object of `type`/`subtype`; unknown subtypes give an inert object
// (isValid() false) after one warning. NULL only for non-object types.
Object *createObject(
    Device &device, ANARIDataType type, const std::string &subtype);

// Objects of a subtype the device does not implement: accept parameters,
// never render.
class UnknownObject : public Object
{
 public:
  using Object::Object;
  bool isValid() const override
  {
    return false;
  }

 protected:
  void commitParameters() override;
};

} // namespace prism
