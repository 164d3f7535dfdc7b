// A measured luminous intensity distribution (IES, EULUMDAT) in the C-gamma
// system (spec 5.7.4): the first array dimension spans gamma in [0, pi]
// from the light's axis (first value at 0, last at pi); an optional second
// dimension spans the C half-planes around the axis, row k at
// C = 2 pi k / rows, the first row also at 2 pi. Interpolated linearly in
// both angles.
#pragma once

#include "../math/Vec.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace prism {
class Array;
} // namespace prism

namespace prism::light {

class IntensityDistribution
{
 public:
  bool empty() const
  {
    return m_values.empty();
  }
  // Takes an ARRAY1D/ARRAY2D of FLOAT32 already checked by the caller;
  // false (and no table) with `why` set when the values are unusable.
  bool assign(const Array &array, const char *&why);

  // The relative intensity towards `local`, a unit vector in the light's
  // frame: +z the gamma = 0 axis, +x the C0 half-plane, +y at C = pi / 2.
  float operator()(float3 local) const;
  // Integral over the sphere of the distribution times `weight(gamma)`
  // (steradians times the table's unit).
  double integral(const std::function<double(double gamma)> &weight,
      std::vector<double> breakpoints) const;

 private:
  std::vector<float> m_values; // gamma-major: value(g, k) at g + k * count
  std::vector<float> m_averageOverC; // per gamma sample, for integrals
  size_t m_gammaCount{0};
  size_t m_cCount{0};
};

} // namespace prism::light
