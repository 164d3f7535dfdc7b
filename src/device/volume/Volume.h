// ANARIVolume: a volumetric object placed in a group (spec 5.12). A volume
// is a medium that absorbs and emits: at each point an extinction (per
// unit length, in the volume's object space) and the colour the absorbed
// fraction is replaced by. Renderers ask for nothing else, plus a
// majorant grid that bounds the extinction region by region.
#pragma once

#include "../object/Object.h"
#include "MajorantGrid.h"

namespace prism {

class Volume : public Object
{
 public:
  Volume(DeviceState &device, const std::string &subtype);

  bool isValid() const override
  {
    return m_valid;
  }
  bool visible() const
  {
    return m_visible;
  }
  // The user's id for the objectId frame channel (~0u when unset).
  uint32_t id() const
  {
    return m_id;
  }
  // Where the medium is, in object space.
  virtual box3 bounds() const = 0;
  // The extinction coefficient and emitted colour at `position` (object
  // space); false where the volume has no value (extinction then 0).
  virtual bool sample(
      const float3 &position, float &extinction, float3 &color) const = 0;
  // Bounds of the extinction over regions of bounds(), for skipping empty
  // space and for tracking collisions with majorants.
  const MajorantGrid &majorants() const
  {
    return m_majorants;
  }
  // The distance between samples at a sampling rate of 1 (object space).
  virtual float cellSize() const = 0;
  // sample() at start + i * step for i < count (points within bounds()),
  // possibly from tables finer than any transfer function's entries: the
  // fast path of ray marchers. The default calls sample() for each.
  virtual void sampleLine(const float3 &start,
      const float3 &step,
      int count,
      float *extinction,
      float3 *color) const;

 protected:
  void commitParameters() final;
  // Reads the subtype's parameters; false after reporting what is wrong.
  virtual bool readVolume() = 0;
  // The largest extinction sample() can return where the field's values
  // lie in [lo, hi].
  virtual float maxExtinction(float lo, float hi) const = 0;
  // The range of field values over an object-space region (see
  // SpatialField::valueRange).
  virtual void valueRange(const box3 &region, float &lo, float &hi) const = 0;

 private:
  bool m_valid{false};
  bool m_visible{true};
  uint32_t m_id{~0u};
  MajorantGrid m_majorants;
};

// The volume of `subtype`, or NULL if there is no such subtype.
Volume *createVolume(DeviceState &device, const std::string &subtype);

} // namespace prism
