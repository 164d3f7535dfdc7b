// ANARILight (spec 5.7): the parameters every light shares and placement
// into world space. Subtypes read their own parameters in object space;
// place() applies an instance's transform to positions and directions only,
// never to sizes or intensities (spec 5.7).
#pragma once

#include "../math/Vec.h"
#include "../object/Object.h"
#include "ConeFalloff.h"
#include "IntensityDistribution.h"
#include "PlacedLight.h"

#include <initializer_list>
#include <memory>

namespace prism {

class Array;

class Light : public Object
{
 public:
  Light(DeviceState &device, const std::string &subtype);

  bool isValid() const override
  {
    return m_valid;
  }
  // This light in world space for one instance placement; NULL while the
  // light is invalid. Call after finalize().
  virtual std::unique_ptr<PlacedLight> place(
      const mat3x4 &worldFromObject) const = 0;

  // The unitless filter applied to all emission.
  float3 color() const
  {
    return m_color;
  }
  // KHR_LIGHT_PRIMARY_VISIBILITY.
  bool visible() const
  {
    return m_visible;
  }

 protected:
  // Reads color and visible and marks the light valid; subtypes call it
  // first from their own commitParameters().
  void commitParameters() override;

  // Which of a precedence list of brightness parameters is in effect (the
  // first explicitly set, else the first with its default) and its value.
  struct Brightness
  {
    size_t source{0}; // index into the list
    float value{1.f};
  };
  Brightness readBrightness(std::initializer_list<const char *> precedence);
  // A declared parameter (Object::param(): default and bounds from the
  // definitions). A number above the maximum is clamped to it with a
  // warning; one below the minimum, not a number or not an accepted value
  // is reported and makes the light invalid (it has no physical meaning).
  template <typename T>
  T lightParam(const char *name)
  {
    T value;
    const ParamCheck check = checkedParam(name, value);
    if (check.verdict == ParamVerdict::kAboveMaximum)
      reportRejected(check);
    else if (check.verdict != ParamVerdict::kAccepted)
      invalidate("%s", check.problem.c_str());
    return value;
  }
  // `color`: finite and >= 0, else the light is invalid. The definitions'
  // maximum (1, 1, 1) is advisory: a color above 1 is HDR input, taken as
  // set without a warning.
  float3 readColor();
  // A FLOAT32 that must be finite and >= 0; otherwise reported, the light
  // becomes invalid and 0 is returned.
  float readNonNegative(const char *name);
  // A FLOAT32_VEC3 that must be finite (positions, edges).
  float3 readFinite(const char *name);
  // A FLOAT32_VEC3 that must be finite and of non-zero length; normalised.
  float3 readDirection(const char *name);
  // openingAngle and falloffAngle (spot, ring), clamped to the ranges the
  // spec describes with a warning.
  light::ConeFalloff readConeFalloff();
  // The optional intensityDistribution (ARRAY1D/2D of FLOAT32), or NULL.
  // NOTE: the committed parameter keeps the array alive until the next
  // commit, so the pointer is only for the finalize() that follows.
  Array *readIntensityDistribution();
  // The table of `array` (NULL gives none); reports unusable values and
  // invalidates the light.
  std::shared_ptr<const light::IntensityDistribution>
  buildIntensityDistribution(const Array *array);
  // Reports why the light cannot be used and marks it invalid.
  void invalidate(const char *format, ...)
      __attribute__((format(printf, 2, 3)));
  // Copies what every placed light shares (primary visibility).
  void placeShared(PlacedLight &placed) const
  {
    placed.visibleToCamera = m_visible;
  }

  float3 m_color{1.f, 1.f, 1.f};
  bool m_visible{true};
  bool m_valid{true};
};

// The light of `subtype`, or NULL if the device does not implement it.
Light *createLight(DeviceState &device, const std::string &subtype);

} // namespace prism
