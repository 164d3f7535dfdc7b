// The angular profile of the spot and ring lights (spec 5.7.5, 5.7.6): full
// inside the core cone (openingAngle - 2 falloffAngle, full angles), zero
// outside openingAngle, and in between a smoothstep of the angle from the
// rim, so falloffAngle is exactly the width of the transition.
#pragma once

namespace prism::light {

class ConeFalloff
{
 public:
  ConeFalloff() = default;
  // Full opening angle in [0, 2 pi]; falloff in [0, openingAngle / 2].
  ConeFalloff(float openingAngle, float falloffAngle);

  // The profile at angle acos(cosTheta) from the axis, in [0, 1].
  float operator()(float cosTheta) const;
  // The same at an angle (radians) from the axis.
  float atAngle(float theta) const;
  // The same in double, for integrals that must see jumps exactly.
  double atAngle(double theta) const;
  // Integral over the sphere of the profile times cos(theta) clamped at 0
  // (`cosineWeighted`) or times 1 (steradians).
  double integral(bool cosineWeighted) const;
  float halfAngle() const
  {
    return m_halfAngle;
  }
  float innerAngle() const
  {
    return m_innerAngle;
  }

 private:
  float m_halfAngle{1.5707964f};
  float m_innerAngle{1.5707964f};
  float m_cosOuter{0.f};
  float m_cosInner{0.f};
};

} // namespace prism::light
