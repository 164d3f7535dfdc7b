// Decoding of array and parameter elements of every numeric ANARI element
// type into the float / unsigned values renderers read, by the spec's rules.
#pragma once

#include "../math/Vec.h"

#include "anari/anari.h"

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

namespace prism {

// ---------------------------------------------------------------------------
// Scalar decoders

// IEEE 754 binary16 bits to float; exact for every value, including
// subnormals, infinities and NaN payloads.
inline float halfToFloat(uint16_t bits)
{
  const uint32_t sign = uint32_t(bits & 0x8000u) << 16;
  const uint32_t exponent = (bits >> 10) & 0x1fu;
  const uint32_t mantissa = bits & 0x3ffu;
  // Subnormals are mantissa * 2^-24: normalise in integers (float maths
  // would flush them under the FTZ mode renderers enable for Embree).
  const uint32_t width = uint32_t(std::bit_width(mantissa));
  const uint32_t subnormal =
      mantissa == 0
          ? 0u
          : ((width + 102u) << 23) | ((mantissa << (24u - width)) & 0x7fffffu);
  // Infinity / NaN keep their payload; normals rebias the exponent 15 -> 127.
  const uint32_t special = 0x7f800000u | (mantissa << 13);
  const uint32_t normal = ((exponent + 112u) << 23) | (mantissa << 13);
  // Selects rather than early returns, so bulk loops can vectorise.
  const uint32_t magnitude =
      exponent == 0 ? subnormal : (exponent == 31 ? special : normal);
  return std::bit_cast<float>(sign | magnitude);
}

// The sRGB EOTF: encoded value in [0, 1] to linear intensity.
float srgbToLinear(float encoded);
// The sRGB OETF (inverse of srgbToLinear): linear intensity to encoded value.
float linearToSrgb(float linear);

// Each 8-bit sRGB code c decoded exactly: srgbToLinear(c / 255) evaluated in
// high precision and rounded once to float.
extern const std::array<float, 256> kSrgb8ToLinear;

inline float srgb8ToLinear(uint8_t code)
{
  return kSrgb8ToLinear[code];
}

// ---------------------------------------------------------------------------
// Element decoders. Supported for float: INT*, UINT*, FIXED*, UFIXED*,
// FLOAT16/32/64 with 1-4 components and the four UFIXED8_*_SRGB types.
// Integers convert by value; UFIXED divides by the type's maximum; FIXED
// divides by its maximum and clamps at -1 (so -128 and -127 both give -1);
// sRGB colour channels go through the EOTF while alpha stays linear.
// Components a type lacks are (0, 0, 0, 1); UFIXED8_RA_SRGB decodes to
// (r, 0, 0, a) because its second value is alpha.

bool canReadAsFloat4(ANARIDataType type);

// One element at `element` (any alignment); (0, 0, 0, 1) for unsupported
// types.
float4 readAsFloat4(ANARIDataType type, const void *element);

// Bulk conversion of `count` elements starting at `begin`, element i at
// begin + i * strideBytes (0 means tightly packed). Outputs of fewer than
// four components keep the leading ones of readAsFloat4. Unsupported types
// write the defaults (0, 0, 0, 1) truncated to the output size.
void convertToFloat4(ANARIDataType type,
    const void *begin,
    size_t count,
    size_t strideBytes,
    float4 *out);
void convertToFloat3(ANARIDataType type,
    const void *begin,
    size_t count,
    size_t strideBytes,
    float3 *out);
void convertToFloat2(ANARIDataType type,
    const void *begin,
    size_t count,
    size_t strideBytes,
    float2 *out);
// First component only, e.g. spatial field values or per-vertex radii.
void convertToFloat(ANARIDataType type,
    const void *begin,
    size_t count,
    size_t strideBytes,
    float *out);

// Whether convertToUint32/64 accept `type`: INT* and UINT* of 1-4 components.
bool canReadAsUint(ANARIDataType type);

// Index arrays: every component of each element copied by value, so `out`
// receives count * componentsOf(type) values (UINT32_VEC3 triangles give
// three indices per element). Values wrap modulo 2^32 / 2^64 like a C cast;
// callers range-check indices against their vertex count anyway. Unsupported
// types write zeros.
void convertToUint32(ANARIDataType type,
    const void *begin,
    size_t count,
    size_t strideBytes,
    uint32_t *out);
void convertToUint64(ANARIDataType type,
    const void *begin,
    size_t count,
    size_t strideBytes,
    uint64_t *out);

} // namespace prism
