// Frame channel pixel encoding; the per-pixel writers share the row loops.
#include "PixelFormat.h"

#include "../array/ElementConversion.h"

#include "anari/frontend/type_utility.h"

#include <cstring>

namespace prism {

bool isValidColorFormat(ANARIDataType format)
{
  return format == ANARI_UFIXED8_VEC4 || format == ANARI_UFIXED8_RGBA_SRGB
         || format == ANARI_FLOAT32_VEC4;
}

bool isValidDepthFormat(ANARIDataType format)
{
  return format == ANARI_FLOAT32;
}

bool isValidNormalFormat(ANARIDataType format)
{
  return format == ANARI_FIXED16_VEC3 || format == ANARI_FLOAT32_VEC3;
}

bool isValidAlbedoFormat(ANARIDataType format)
{
  return format == ANARI_UFIXED8_VEC3 || format == ANARI_UFIXED8_RGB_SRGB
         || format == ANARI_FLOAT32_VEC3;
}

bool isValidIdFormat(ANARIDataType format)
{
  return format == ANARI_UINT32;
}

size_t pixelSize(ANARIDataType format)
{
  const bool valid = isValidColorFormat(format) || isValidDepthFormat(format)
                     || isValidNormalFormat(format)
                     || isValidAlbedoFormat(format) || isValidIdFormat(format);
  return valid ? anari::sizeOf(format) : 0;
}

namespace {

// kSrgb8Threshold[k] is the linear value from which sRGB code k + 1 is the
// nearest (the decoded midpoint of codes k and k + 1): encoding becomes an
// 8-step binary search with exactly the rounding of the formula, instead
// of a pow() per channel on the frame's hot path.
struct SrgbThresholds
{
  float value[255];
  SrgbThresholds()
  {
    for (int k = 0; k < 255; k++)
      value[k] = srgbToLinear((float(k) + 0.5f) / 255.f);
  }
};
const SrgbThresholds kSrgb8Threshold;

// kSrgb8Start[i]: the code of linear value i / 4096. A bucket spans at most
// one threshold (the curve's steepest slope, 12.92, times 255 / 4096 < 1),
// so one comparison finishes the exact encoding.
struct SrgbBuckets
{
  uint8_t code[4097];
  SrgbBuckets()
  {
    int c = 0;
    for (int i = 0; i <= 4096; i++) {
      const float linear = float(i) / 4096.f;
      while (c < 255 && linear >= kSrgb8Threshold.value[c])
        c++;
      code[i] = uint8_t(c);
    }
  }
};
const SrgbBuckets kSrgb8Start;

} // namespace

uint8_t toSrgb8(float linear)
{
  if (!(linear > 0.f)) // also NaN
    return 0;
  if (linear >= 1.f)
    return 255;
  const int code = kSrgb8Start.code[int(linear * 4096.f)];
  return uint8_t(
      code < 255 && linear >= kSrgb8Threshold.value[code] ? code + 1 : code);
}

void writeColorPixels(
    ANARIDataType format, const float4 *linearRGBA, size_t count, void *dst)
{
  auto *bytes = static_cast<uint8_t *>(dst);
  switch (int(format)) {
  case ANARI_UFIXED8_VEC4:
    for (size_t i = 0; i < count; i++) {
      const float4 &c = linearRGBA[i];
      uint8_t *p = bytes + 4 * i;
      p[0] = toUnorm8(c.x);
      p[1] = toUnorm8(c.y);
      p[2] = toUnorm8(c.z);
      p[3] = toUnorm8(c.w);
    }
    break;
  case ANARI_UFIXED8_RGBA_SRGB: {
    // Runs of one color (a plain background) are encoded once; the pixel
    // is kept as one 32-bit word and so stored.
    uint32_t pixel = 0;
    for (size_t i = 0; i < count; i++) {
      const float4 &c = linearRGBA[i];
      if (i == 0 || std::memcmp(&c, &linearRGBA[i - 1], sizeof(float4)) != 0) {
        const uint8_t codes[4] = {
            toSrgb8(c.x), toSrgb8(c.y), toSrgb8(c.z), toUnorm8(c.w)};
        std::memcpy(&pixel, codes, sizeof(pixel));
      }
      std::memcpy(bytes + 4 * i, &pixel, sizeof(pixel));
    }
    break;
  }
  case ANARI_FLOAT32_VEC4:
    std::memcpy(dst, linearRGBA, count * sizeof(float4));
    break;
  default:
    break;
  }
}

void writeVec3Pixels(
    ANARIDataType format, const float3 *values, size_t count, void *dst)
{
  auto *bytes = static_cast<uint8_t *>(dst);
  switch (int(format)) {
  case ANARI_UFIXED8_VEC3:
    for (size_t i = 0; i < count; i++) {
      uint8_t *p = bytes + 3 * i;
      p[0] = toUnorm8(values[i].x);
      p[1] = toUnorm8(values[i].y);
      p[2] = toUnorm8(values[i].z);
    }
    break;
  case ANARI_UFIXED8_RGB_SRGB:
    for (size_t i = 0; i < count; i++) {
      uint8_t *p = bytes + 3 * i;
      p[0] = toSrgb8(values[i].x);
      p[1] = toSrgb8(values[i].y);
      p[2] = toSrgb8(values[i].z);
    }
    break;
  case ANARI_FIXED16_VEC3:
    for (size_t i = 0; i < count; i++) {
      const int16_t p[3] = {toSnorm16(values[i].x),
          toSnorm16(values[i].y),
          toSnorm16(values[i].z)};
      // The mapped buffer need not be 2-byte aligned for us; copy bytes.
      std::memcpy(bytes + sizeof(p) * i, p, sizeof(p));
    }
    break;
  case ANARI_FLOAT32_VEC3:
    std::memcpy(dst, values, count * sizeof(float3));
    break;
  default:
    break;
  }
}

void writeColor(ANARIDataType format, const float4 &linearRGBA, void *dst)
{
  writeColorPixels(format, &linearRGBA, 1, dst);
}

void writeVec3(ANARIDataType format, const float3 &value, void *dst)
{
  writeVec3Pixels(format, &value, 1, dst);
}

void writeDepth(ANARIDataType format, float depth, void *dst)
{
  if (isValidDepthFormat(format))
    std::memcpy(dst, &depth, sizeof(depth));
}

void writeId(ANARIDataType format, uint32_t id, void *dst)
{
  if (isValidIdFormat(format))
    std::memcpy(dst, &id, sizeof(id));
}

} // namespace prism
