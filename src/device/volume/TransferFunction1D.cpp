#include "TransferFunction1D.h"

#include "../array/Array.h"
#include "../array/ElementConversion.h"

#include "anari/frontend/type_utility.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prism {
namespace {

// Opacity is capped here: 1 would mean an infinite extinction.
constexpr float kMaxOpacity = 1.f - 1e-6f;

// u clamped to [0, 1], NaN (an infinite value over an empty valueRange)
// to 0: every table index stays in range.
float unitClamp(float u)
{
  return u > 0.f ? (u < 1.f ? u : 1.f) : 0.f;
}

// The table entry at normalised position u in [0, 1], linearly
// interpolated between entries (the first at 0, the last at 1).
template <typename T>
T lookup(const std::vector<T> &table, float u)
{
  const size_t last = table.size() - 1;
  if (last == 0)
    return table[0];
  const float x = unitClamp(u) * float(last);
  const size_t i = std::min(size_t(x), last - 1);
  const float f = x - float(i);
  return table[i] * (1.f - f) + table[i + 1] * f;
}

// The largest entry the table can give over normalised [u0, u1]: the
// interpolated ends and every entry between them.
template <typename T, typename Get>
float tableMax(const std::vector<T> &table, float u0, float u1, Get get)
{
  // NaN ends (an unknown range) span the whole table.
  if (!(u0 == u0) || !(u1 == u1)) {
    u0 = 0.f;
    u1 = 1.f;
  }
  float best = std::max(get(lookup(table, u0)), get(lookup(table, u1)));
  const size_t last = table.size() - 1;
  const float x0 = unitClamp(u0) * float(last);
  const float x1 = unitClamp(u1) * float(last);
  for (size_t i = size_t(std::ceil(x0)); float(i) <= x1 && i <= last; i++)
    best = std::max(best, get(table[i]));
  return best;
}

} // namespace

TransferFunction1D::TransferFunction1D(DeviceState &device)
    : Volume(device, "transferFunction1D")
{}

bool TransferFunction1D::readVolume()
{
  float low = 0.f, high = 1.f;
  if (const Parameter *range = readAny("valueRange")) {
    if (range->type() == ANARI_FLOAT32_BOX1) {
      const auto box = range->as<float2>();
      low = box.x;
      high = box.y;
    } else if (range->type() == ANARI_FLOAT64_BOX1) {
      const auto box = range->as<double2>();
      low = float(box.x);
      high = float(box.y);
    } else {
      wrongType("valueRange",
          range->type(),
          {ANARI_FLOAT32_BOX1, ANARI_FLOAT64_BOX1});
    }
  }
  if (!std::isfinite(low) || !std::isfinite(high) || high < low) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'valueRange' [%g, %g] is not a finite range; [0, 1] is used",
        double(low),
        double(high));
    low = 0.f;
    high = 1.f;
  }
  m_valueLow = low;
  // A range too narrow for its reciprocal still sorts values below, in
  // and above it (never inf * 0).
  m_valueScale = high > low ? std::min(
                     1.f / (high - low), std::numeric_limits<float>::max())
                            : 0.f;
  m_unitDistance = read<float>("unitDistance", ANARI_FLOAT32, 1.f);
  if (!(m_unitDistance > 0.f) || !std::isfinite(m_unitDistance)) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'unitDistance' %g is not positive and finite; 1 is used",
        double(m_unitDistance));
    m_unitDistance = 1.f;
  }
  // Every parameter is read before any is judged, so each is checked.
  const bool tables = readColors() & readOpacities();
  m_table.resize(kTableSize + 1);
  for (int i = 0; i <= kTableSize; i++) {
    const float u = float(i) / float(kTableSize);
    const float4 c = classifyNormalized(u);
    m_table[size_t(i)] = {c.x, c.y, c.z, extinctionOf(c.w)};
  }
  m_field = static_cast<const SpatialField *>(
      readObject("value", {ANARI_SPATIAL_FIELD}));
  if (!m_field || !m_field->isValid()) {
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_ARGUMENT,
        m_field ? "'value' is an invalid spatial field; the volume is skipped"
                : "required parameter 'value' (a spatial field) is not set; "
                  "the volume is skipped");
    return false;
  }
  return tables;
}

bool TransferFunction1D::readColors()
{
  m_colors.assign(1, float4{1.f, 1.f, 1.f, 1.f});
  const Parameter *color = readAny("color");
  if (!color)
    return true;
  if (color->type() == ANARI_FLOAT32_VEC4) {
    m_colors[0] = color->as<float4>();
  } else if (color->type() == ANARI_FLOAT32_VEC3) {
    const auto rgb = color->as<float3>();
    m_colors[0] = {rgb.x, rgb.y, rgb.z, 1.f};
  } else if (color->type() == ANARI_ARRAY1D && color->object()) {
    auto *array = static_cast<const Array *>(color->object());
    dependOn(color->object());
    if (array->count() == 0 || !canReadAsFloat4(array->elementType())) {
      report(ANARI_SEVERITY_ERROR,
          ANARI_STATUS_INVALID_ARGUMENT,
          "'color' array is empty or of element type %s, which is not a "
          "color; the volume is skipped",
          anari::toString(array->elementType()));
      return false;
    }
    m_colors.resize(array->count());
    convertToFloat4(array->elementType(),
        array->begin(),
        m_colors.size(),
        array->elementSize(),
        m_colors.data());
  } else {
    wrongType("color",
        color->type(),
        {ANARI_FLOAT32_VEC4, ANARI_FLOAT32_VEC3, ANARI_ARRAY1D});
  }
  for (float4 &c : m_colors) {
    // Non-finite table entries would poison every sample they touch.
    c = {std::isfinite(c.x) ? c.x : 0.f,
        std::isfinite(c.y) ? c.y : 0.f,
        std::isfinite(c.z) ? c.z : 0.f,
        std::isfinite(c.w) ? std::clamp(c.w, 0.f, 1.f) : 0.f};
  }
  return true;
}

bool TransferFunction1D::readOpacities()
{
  m_opacities.assign(1, 1.f);
  const Parameter *opacity = readAny("opacity");
  if (!opacity)
    return true;
  if (opacity->type() == ANARI_FLOAT32) {
    m_opacities[0] = opacity->as<float>();
  } else if (opacity->type() == ANARI_ARRAY1D && opacity->object()) {
    auto *array = static_cast<const Array *>(opacity->object());
    dependOn(opacity->object());
    if (array->count() == 0 || array->elementType() != ANARI_FLOAT32) {
      report(ANARI_SEVERITY_ERROR,
          ANARI_STATUS_INVALID_ARGUMENT,
          "'opacity' array is empty or of element type %s (FLOAT32 is "
          "accepted); the volume is skipped",
          anari::toString(array->elementType()));
      return false;
    }
    m_opacities.resize(array->count());
    convertToFloat(ANARI_FLOAT32,
        array->begin(),
        m_opacities.size(),
        array->elementSize(),
        m_opacities.data());
  } else {
    wrongType("opacity", opacity->type(), {ANARI_FLOAT32, ANARI_ARRAY1D});
  }
  for (float &o : m_opacities)
    o = std::isfinite(o) ? std::clamp(o, 0.f, 1.f) : 0.f;
  return true;
}

box3 TransferFunction1D::bounds() const
{
  return m_field->bounds();
}

float TransferFunction1D::cellSize() const
{
  return m_field->cellSize();
}

float4 TransferFunction1D::classify(float value) const
{
  return classifyNormalized((value - m_valueLow) * m_valueScale);
}

float4 TransferFunction1D::classifyNormalized(float u) const
{
  const float4 color = lookup(m_colors, u);
  return {color.x, color.y, color.z, color.w * lookup(m_opacities, u)};
}

float TransferFunction1D::extinctionOf(float opacity) const
{
  return -std::log1p(-std::min(opacity, kMaxOpacity)) / m_unitDistance;
}

bool TransferFunction1D::sample(
    const float3 &position, float &extinction, float3 &color) const
{
  const float value = m_field->sample(position);
  if (std::isnan(value)) {
    extinction = 0.f;
    return false;
  }
  const float4 c = classify(value);
  extinction = extinctionOf(c.w);
  color = {c.x, c.y, c.z};
  return true;
}

void TransferFunction1D::sampleLine(const float3 &start,
    const float3 &step,
    int count,
    float *extinction,
    float3 *color) const
{
  constexpr int kBatch = 64;
  float values[kBatch];
  for (int first = 0; first < count; first += kBatch) {
    const int n = std::min(kBatch, count - first);
    m_field->sampleLine(start + step * float(first), step, n, values);
    for (int i = 0; i < n; i++) {
      const float v = values[i];
      const bool valued = v == v; // NaN: no value, no extinction
      const float x = valued ? unitClamp((v - m_valueLow) * m_valueScale)
                                   * float(kTableSize)
                             : 0.f;
      const int k = std::min(int(x), kTableSize - 1);
      const float f = x - float(k);
      const float4 entry =
          m_table[size_t(k)] * (1.f - f) + m_table[size_t(k) + 1] * f;
      extinction[first + i] = valued ? entry.w : 0.f;
      color[first + i] = {entry.x, entry.y, entry.z};
    }
  }
}

float TransferFunction1D::maxExtinction(float lo, float hi) const
{
  // The colour's alpha and the opacity peak separately, so their product
  // is bounded by the product of their peaks.
  const float u0 = (lo - m_valueLow) * m_valueScale;
  const float u1 = (hi - m_valueLow) * m_valueScale;
  const float alpha =
      tableMax(m_colors, u0, u1, [](const float4 &c) { return c.w; });
  const float opacity =
      tableMax(m_opacities, u0, u1, [](float o) { return o; });
  return extinctionOf(alpha * opacity);
}

void TransferFunction1D::valueRange(
    const box3 &region, float &lo, float &hi) const
{
  m_field->valueRange(region, lo, hi);
}

} // namespace prism
