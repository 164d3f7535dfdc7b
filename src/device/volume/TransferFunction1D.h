// The transferFunction1D volume (KHR_VOLUME_TRANSFER_FUNCTION1D): a
// spatial field's values, clamped to valueRange, index a colour table and
// an opacity table (each linearly interpolated, sizes independent); the
// final opacity (colour alpha times opacity) is the fraction of light
// absorbed over unitDistance, so the extinction is
// -ln(1 - opacity) / unitDistance, and the absorbed light is replaced by
// the colour (spec 5.12.1 and its Appendix C).
#pragma once

#include "../object/ObjectRef.h"
#include "SpatialField.h"
#include "Volume.h"

#include <vector>

namespace prism {

class TransferFunction1D : public Volume
{
 public:
  explicit TransferFunction1D(DeviceState &device);

  box3 bounds() const override;
  bool sample(
      const float3 &position, float &extinction, float3 &color) const override;
  float cellSize() const override;
  // Through a table of colour and extinction by value (kTableSize entries
  // over valueRange, linearly interpolated): no logarithm per sample.
  void sampleLine(const float3 &start,
      const float3 &step,
      int count,
      float *extinction,
      float3 *color) const override;

  // The colour and final opacity the table gives field value `value`.
  float4 classify(float value) const;
  // The same for a value's position u in valueRange (0 at its start, 1 at
  // its end).
  float4 classifyNormalized(float u) const;
  // The extinction of an opacity (capped just below 1, where the density
  // would be infinite).
  float extinctionOf(float opacity) const;

 protected:
  bool readVolume() override;
  float maxExtinction(float lo, float hi) const override;
  void valueRange(const box3 &region, float &lo, float &hi) const override;

 private:
  bool readColors();
  bool readOpacities();

  const SpatialField *m_field{nullptr};
  float m_valueLow{0.f};
  float m_valueScale{1.f}; // 1 / (high - low), 0 for an empty range
  std::vector<float4> m_colors;
  std::vector<float> m_opacities;
  float m_unitDistance{1.f};
  static constexpr int kTableSize = 1024;
  std::vector<float4> m_table; // colour and extinction, by value
};

} // namespace prism
