// The pixel types a frame channel may be mapped as (spec, frame section) and
// the encoding of one rendered value into each of them.
#pragma once

#include "../math/Vec.h"

#include "anari/anari.h"

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace prism {

// channel.color: UFIXED8_VEC4, UFIXED8_RGBA_SRGB, FLOAT32_VEC4.
bool isValidColorFormat(ANARIDataType format);
// channel.depth: FLOAT32.
bool isValidDepthFormat(ANARIDataType format);
// channel.normal: FIXED16_VEC3, FLOAT32_VEC3.
bool isValidNormalFormat(ANARIDataType format);
// channel.albedo: UFIXED8_VEC3, UFIXED8_RGB_SRGB, FLOAT32_VEC3.
bool isValidAlbedoFormat(ANARIDataType format);
// channel.primitiveId / objectId / instanceId: UINT32.
bool isValidIdFormat(ANARIDataType format);

// Bytes per pixel of any channel format above; 0 for every other type.
size_t pixelSize(ANARIDataType format);

// [0, 1] to the nearest 8-bit code; NaN encodes as 0.
inline uint8_t toUnorm8(float v)
{
  const float clamped = v > 0.f ? (v < 1.f ? v : 1.f) : 0.f;
  return uint8_t(clamped * 255.f + 0.5f);
}

// [-1, 1] to the nearest 16-bit signed code (Vulkan SNORM); NaN gives 0.
inline int16_t toSnorm16(float v)
{
  if (std::isnan(v))
    return 0;
  const float clamped = v < -1.f ? -1.f : (v > 1.f ? 1.f : v);
  return int16_t(std::lround(clamped * 32767.f));
}

// Linear intensity to the nearest 8-bit sRGB code (OETF after clamping).
uint8_t toSrgb8(float linear);

// One pixel of a colour format from linear RGBA: UFIXED8 clamps and rounds,
// SRGB encodes RGB with the OETF and keeps alpha linear, FLOAT32 is raw.
// Invalid formats write nothing.
void writeColor(ANARIDataType format, const float4 &linearRGBA, void *dst);

// One pixel of a three-component format: albedo (linear RGB, encoded like
// writeColor), or normal (FIXED16_VEC3 as SNORM, FLOAT32_VEC3 raw).
void writeVec3(ANARIDataType format, const float3 &value, void *dst);

// One pixel of channel.depth / the id channels (FLOAT32 / UINT32).
void writeDepth(ANARIDataType format, float depth, void *dst);
void writeId(ANARIDataType format, uint32_t id, void *dst);

// A row of pixels at once: the format switch runs once, not per pixel.
void writeColorPixels(
    ANARIDataType format, const float4 *linearRGBA, size_t count, void *dst);
void writeVec3Pixels(
    ANARIDataType format, const float3 *values, size_t count, void *dst);

} // namespace prism
