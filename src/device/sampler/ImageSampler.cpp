#include "ImageSampler.h"

#include <algorithm>
#include <cmath>

namespace prism {
namespace {

// Texel coordinates are clamped to +-2^52 so they convert to int64 exactly.
constexpr double kCoordinateLimit = 4503599627370496.0;

// Vulkan's wrapping of an integer texel index into [0, n); -1 means the
// border colour.
int64_t wrapIndex(int64_t i, int64_t n, WrapMode wrap)
{
  switch (wrap) {
  case WrapMode::Repeat: {
    const int64_t r = i % n;
    return r < 0 ? r + n : r;
  }
  case WrapMode::MirrorRepeat: {
    // Every other repetition runs backwards: ..., 1, 0 | 0, 1, ..., n-1 |
    // n-1, ...
    int64_t t = i % (2 * n);
    if (t < 0)
      t += 2 * n;
    return t < n ? t : 2 * n - 1 - t;
  }
  case WrapMode::ClampToBorder:
    return i < 0 || i >= n ? -1 : i;
  default:
    return std::clamp<int64_t>(i, 0, n - 1);
  }
}

} // namespace

ImageSampler::ImageSampler(DeviceState &device,
    const std::string &subtype,
    int dimensions,
    std::array<const char *, 3> wrapParameters,
    bool (*acceptsElementType)(ANARIDataType))
    : Sampler(device, subtype),
      m_dimensions(dimensions),
      m_wrapParameters(wrapParameters),
      m_acceptsElementType(acceptsElementType)
{}

void ImageSampler::commitParameters()
{
  Sampler::commitParameters();
  const ANARIDataType arrayType = m_dimensions == 1   ? ANARI_ARRAY1D
                                  : m_dimensions == 2 ? ANARI_ARRAY2D
                                                      : ANARI_ARRAY3D;
  m_image = readColorArray("image", arrayType, m_acceptsElementType);
  m_inAttribute = readInAttribute();
  m_inTransform = param<mat4>("inTransform");
  m_inOffset = param<float4>("inOffset");
  // The spec: unknown filters give the default (linear).
  m_filter = param<std::string>("filter") == "nearest" ? Filter::Nearest
                                                       : Filter::Linear;
  for (int d = 0; d < m_dimensions; d++)
    m_wrap[d] = readWrapMode(m_wrapParameters[d]);
  m_borderColor = param<float4>("borderColor");
}

WrapMode ImageSampler::readWrapMode(const char *name)
{
  // An unknown mode is reported and the default, clampToEdge, used.
  const std::string mode = param<std::string>(name);
  if (mode == "repeat")
    return WrapMode::Repeat;
  if (mode == "mirrorRepeat")
    return WrapMode::MirrorRepeat;
  if (mode == "clampToBorder")
    return WrapMode::ClampToBorder;
  return WrapMode::ClampToEdge;
}

void ImageSampler::finalize()
{
  // Released first so an image change never holds two copies at once.
  std::vector<float4>().swap(m_texels);
  m_size[0] = m_size[1] = m_size[2] = 1;
  if (!m_image)
    return;
  const Array &image = *m_image.get();
  for (int d = 0; d < m_dimensions; d++) {
    m_size[d] = m_dimensions == 1 ? image.count() : image.size(d);
    m_stride[d] = d == 0 ? 1 : m_stride[d - 1] * m_size[d - 1];
  }
  convertColors(image, m_texels);
}

void ImageSampler::dropReferences()
{
  Sampler::dropReferences();
  m_image.reset();
}

ImageSampler::Tap ImageSampler::tapAt(float coordinate, int dimension) const
{
  const int64_t n = int64_t(m_size[dimension]);
  const WrapMode wrap = m_wrap[dimension];
  // Texel units in double keep indices exact far beyond float's 24 bits;
  // NaN samples texel 0.
  double x = double(coordinate) * double(n);
  x = std::isnan(x) ? 0.0 : std::clamp(x, -kCoordinateLimit, kCoordinateLimit);
  if (m_filter == Filter::Nearest) {
    const int64_t i = wrapIndex(int64_t(std::floor(x)), n, wrap);
    return {{i, i}, 0.f};
  }
  // Linear: the two texel centres ((i + 0.5) / n) around the coordinate.
  x -= 0.5;
  const double base = std::floor(x);
  const int64_t i = int64_t(base);
  return {{wrapIndex(i, n, wrap), wrapIndex(i + 1, n, wrap)}, float(x - base)};
}

float4 ImageSampler::blend(
    const Tap *taps, int dimension, uint64_t offset, bool border) const
{
  if (dimension < 0)
    return border ? m_borderColor : m_texels[offset];
  const Tap &tap = taps[dimension];
  auto side = [&](int s) {
    const int64_t i = tap.index[s];
    return blend(taps,
        dimension - 1,
        offset + uint64_t(i < 0 ? 0 : i) * m_stride[dimension],
        border || i < 0);
  };
  const float4 a = side(0);
  if (tap.weight == 0.f)
    return a; // nearest filtering and texel centres read one texel
  // a + (b - a) w rather than lerp(): equal texels blend to themselves.
  return a + (side(1) - a) * tap.weight;
}

float4 ImageSampler::lookup(float4 coordinates) const
{
  if (m_texels.empty())
    return {0.f, 0.f, 0.f, 1.f};
  Tap taps[3]{};
  for (int d = 0; d < m_dimensions; d++)
    taps[d] = tapAt(coordinates[d], d);
  return blend(taps, m_dimensions - 1, 0, false);
}

float4 ImageSampler::sample(const AttributeValues &attributes) const
{
  const float4 coordinates =
      m_inTransform * attributes[m_inAttribute] + m_inOffset;
  return applyOutTransform(lookup(coordinates));
}

} // namespace prism
