// Transform keys uniformly distributed over a time span: the motion blur of
// instances (KHR_INSTANCE_MOTION_TRANSFORM, KHR_INSTANCE_MOTION_SCALE_
// ROTATION_TRANSLATION) and cameras (KHR_CAMERA_MOTION_TRANSFORMATION).
// Matrices interpolate linearly; decomposed keys interpolate scale and
// translation linearly and rotation by slerp. Embree traces moving
// instances the same way, so shading at a hit agrees with what was hit.
#pragma once

#include "KeyTimeline.h"
#include "Vec.h"

#include <vector>

namespace prism {

class MotionTransform
{
 public:
  // Scale, then rotation (a unit quaternion i, j, k, w), then translation.
  struct Decomposed
  {
    float3 scale{1, 1, 1};
    float4 rotation{0, 0, 0, 1};
    float3 translation{0, 0, 0};
  };

  // No keys: isSet() is false and at() is the identity.
  MotionTransform() = default;
  MotionTransform(std::vector<mat3x4> keys, float begin, float end);
  // Neighbouring rotations are put into one hemisphere so that every slerp
  // (ours, Embree's) turns the shorter way.
  MotionTransform(std::vector<Decomposed> keys, float begin, float end);

  bool isSet() const
  {
    return !m_matrices.empty() || !m_decomposed.empty();
  }
  bool isDecomposed() const
  {
    return !m_decomposed.empty();
  }
  // Keys are at least one apart in time: the transform changes.
  bool isMoving() const
  {
    return m_timeline.keyCount > 1;
  }
  const KeyTimeline &timeline() const
  {
    return m_timeline;
  }
  mat3x4 at(float time) const;
  // The interpolated components (isDecomposed() only).
  Decomposed decomposedAt(float time) const;
  // The keys themselves, as matrices.
  mat3x4 key(uint32_t index) const;

  static mat3x4 compose(const Decomposed &components);
  static Decomposed interpolate(
      const Decomposed &a, const Decomposed &b, float fraction);
  static float4 slerp(float4 a, float4 b, float fraction);

 private:
  KeyTimeline m_timeline{0, 0.f, 1.f};
  std::vector<mat3x4> m_matrices;
  std::vector<Decomposed> m_decomposed;
};

} // namespace prism
