#include "MotionParameters.h"

#include "Array.h"

#include "../object/FormatText.h"

#include "anari/frontend/type_utility.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>

namespace prism {
namespace {

bool finite(const mat3x4 &m)
{
  for (const float3 &c : m.col) {
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z))
      return false;
  }
  return true;
}

// Element `k` of `keys` keys spread over the same span as `count` values.
template <typename T, typename Mix>
T resampled(const T *values, size_t count, size_t k, size_t keys, Mix mix)
{
  if (count == keys)
    return mix(values[k], values[k], 0.f);
  if (count == 1)
    return values[0];
  const float at = float(k) * float(count - 1) / float(keys - 1);
  const size_t i = std::min(size_t(at), count - 2);
  return mix(values[i], values[i + 1], at - float(i));
}

} // namespace

MotionTransform readMotionTransform(const MotionParameters &p,
    const std::function<void(const std::string &)> &warn)
{
  // The array if it has the expected element type and some keys, or NULL.
  auto usable = [&](const Array *array, const char *name, ANARIDataType type) {
    if (!array)
      return (const Array *)nullptr;
    if (array->elementType() != type) {
      warn(formatText("'%s' has element type %s (expected %s); ignored",
          name,
          anari::toString(array->elementType()),
          anari::toString(type)));
      return (const Array *)nullptr;
    }
    if (array->count() == 0) {
      warn(formatText("'%s' is empty; ignored", name));
      return (const Array *)nullptr;
    }
    return array;
  };
  const Array *matrices =
      usable(p.transform, "motion.transform", ANARI_FLOAT32_MAT4);
  const Array *scale = usable(p.scale, "motion.scale", ANARI_FLOAT32_VEC3);
  const Array *rotation =
      usable(p.rotation, "motion.rotation", ANARI_FLOAT32_QUAT_IJKW);
  const Array *translation =
      usable(p.translation, "motion.translation", ANARI_FLOAT32_VEC3);

  float begin = p.time.x, end = p.time.y;
  if (!(std::isfinite(begin) && std::isfinite(end) && begin < end)
      && (matrices || scale || rotation || translation)) {
    warn(formatText(
        "'time' [%g, %g] is not an interval; using [0, 1]", begin, end));
    begin = 0.f;
    end = 1.f;
  }

  MotionTransform out;
  if (matrices) {
    std::vector<mat3x4> keys;
    const auto *m = (const mat4 *)matrices->begin();
    for (uint64_t i = 0; i < matrices->count(); i++)
      keys.push_back(affineFromMat4(m[i]));
    out = MotionTransform(std::move(keys), begin, end);
  } else if (scale || rotation || translation) {
    const size_t scales = scale ? scale->count() : 0;
    const size_t rotations = rotation ? rotation->count() : 0;
    const size_t translations = translation ? translation->count() : 0;
    const size_t count = std::max({scales, rotations, translations});
    if ((scales && scales != count) || (rotations && rotations != count)
        || (translations && translations != count)) {
      warn(formatText(
          "'motion.scale', 'motion.rotation' and 'motion.translation' have "
          "%zu, %zu and %zu keys; each is resampled to %zu keys",
          scales,
          rotations,
          translations,
          count));
    }
    const auto lerp3 = [](float3 a, float3 b, float t) {
      return a * (1.f - t) + b * t;
    };
    const auto slerp = [](float4 a, float4 b, float t) {
      return MotionTransform::slerp(normalize(a), normalize(b), t);
    };
    std::vector<MotionTransform::Decomposed> keys(count);
    for (size_t k = 0; k < count; k++) {
      if (scale) {
        keys[k].scale =
            resampled((const float3 *)scale->begin(), scales, k, count, lerp3);
      }
      if (rotation) {
        keys[k].rotation = normalize(resampled(
            (const float4 *)rotation->begin(), rotations, k, count, slerp));
      }
      if (translation) {
        keys[k].translation = resampled((const float3 *)translation->begin(),
            translations,
            k,
            count,
            lerp3);
      }
    }
    out = MotionTransform(std::move(keys), begin, end);
  }

  // Hits are mapped back into moving instances and camera rays out of the
  // camera: every key must be finite and invertible.
  for (uint32_t k = 0; k < out.timeline().keyCount && out.isSet(); k++) {
    const mat3x4 m = out.key(k);
    if (!finite(m) || !finite(inverse(m))) {
      warn(formatText(
          "motion key %u is not finite or not invertible; the motion "
          "keys are ignored",
          k));
      return MotionTransform();
    }
  }
  return out;
}

} // namespace prism
