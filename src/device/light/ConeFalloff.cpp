#include "ConeFalloff.h"

#include "Sampling.h"

#include <cmath>

namespace prism::light {
namespace {

// The profile in any precision: the integral needs double so the jump of
// a sharp cone lands exactly on its breakpoint.
template <typename T>
T profileAt(T theta, T halfAngle, T innerAngle)
{
  if (theta <= innerAngle)
    return T(1);
  if (theta >= halfAngle)
    return T(0);
  const T t = (halfAngle - theta) / (halfAngle - innerAngle);
  return t * t * (T(3) - T(2) * t);
}

} // namespace

ConeFalloff::ConeFalloff(float openingAngle, float falloffAngle)
    : m_halfAngle(0.5f * openingAngle),
      m_innerAngle(0.5f * openingAngle - falloffAngle),
      m_cosOuter(std::cos(m_halfAngle)),
      m_cosInner(std::cos(m_innerAngle))
{}

float ConeFalloff::operator()(float cosTheta) const
{
  // Cosine tests first: the acos is needed only inside the transition band.
  if (cosTheta >= m_cosInner)
    return 1.f;
  if (cosTheta <= m_cosOuter && m_halfAngle < kPi)
    return 0.f;
  return atAngle(std::acos(clamp(cosTheta, -1.f, 1.f)));
}

float ConeFalloff::atAngle(float theta) const
{
  return profileAt(theta, m_halfAngle, m_innerAngle);
}

double ConeFalloff::atAngle(double theta) const
{
  return profileAt<double>(theta, m_halfAngle, m_innerAngle);
}

double ConeFalloff::integral(bool cosineWeighted) const
{
  return integrateOverSphere(
      [&](double theta) {
        const double weight =
            cosineWeighted ? std::max(0.0, std::cos(theta)) : 1.0;
        return weight * profileAt<double>(theta, m_halfAngle, m_innerAngle);
      },
      {m_innerAngle, m_halfAngle, 0.5 * kPiDouble});
}

} // namespace prism::light
