// ANARISpatialField: scalar values spread through a local space, sampled
// at any point (spec 5.13). Subtypes: structuredRegular, nanovdb,
// unstructured. Volumes and isosurfaces read fields only through this
// interface.
#pragma once

#include "../math/Vec.h"
#include "../object/Object.h"

#include <string>

namespace prism {

// How a grid field reconstructs values between its samples (the "filter"
// parameter of structuredRegular and nanovdb).
enum class FieldFilter { Nearest, Linear, Cubic };

class SpatialField : public Object
{
 public:
  SpatialField(DeviceState &device, const std::string &subtype);

  // Whether the last commit gave a field that can be sampled (bad input is
  // reported at commit and leaves the field invalid, never half read).
  bool isValid() const override
  {
    return m_valid;
  }
  // The region, in the field's object space, where sample() has values.
  virtual box3 bounds() const = 0;
  // The filtered value at `position` (object space); NaN outside the
  // field's domain (outside bounds(), or in no cell of an unstructured
  // mesh, or in an inactive region of a sparse grid with no background).
  virtual float sample(const float3 &position) const = 0;
  // The gradient of sample() at `position` (object space); the default
  // takes central differences half a cell apart.
  virtual float3 gradient(const float3 &position) const;
  // A conservative range [lo, hi] of every value sample() returns at
  // points of `region` (object space), filter overshoot included; lo > hi
  // when no point of the region has a value. Used to build majorant grids
  // and to skip empty space, so it must be cheap per region and never
  // narrower than the truth.
  virtual void valueRange(const box3 &region, float &lo, float &hi) const = 0;
  // The spacing of the field's data: the step a ray marcher takes at a
  // sampling rate of 1 (one sample per cell).
  virtual float cellSize() const = 0;
  // sample() at start + i * step for i < count, into values: the marcher's
  // inner loop, one call per run of steps. Points must lie within bounds()
  // (a grid clamps those that round just outside). The default calls
  // sample() for each.
  virtual void sampleLine(
      const float3 &start, const float3 &step, int count, float *values) const;

 protected:
  void commitParameters() final;
  // Reads the subtype's parameters and builds what sampling needs; returns
  // false after reporting what is wrong.
  virtual bool readField() = 0;
  // Reads "filter" (nearest, linear or cubic); an unknown name is warned
  // about and gives linear, the spec's default.
  FieldFilter readFilter();
  // `region` clipped to bounds(); false when they do not overlap (or the
  // region has NaN corners), for valueRange().
  bool clipToBounds(const box3 &region, box3 &clipped) const;

 private:
  bool m_valid{false};
};

// The field of `subtype`, or NULL if there is no such subtype.
SpatialField *createSpatialField(
    DeviceState &device, const std::string &subtype);

} // namespace prism
