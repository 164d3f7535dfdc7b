#include "Hdri.h"

#include "../array/Array.h"
#include "../array/ElementConversion.h"
#include "Sampling.h"

#include "anari/frontend/type_utility.h"

#include <cmath>
#include <exception>
#include <limits>

namespace prism::light {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// The spec's FLOAT32_VEC3 and the other float layouts HDR images come in
// (alpha is ignored).
bool isRadianceElementType(ANARIDataType type)
{
  return type == ANARI_FLOAT32_VEC3 || type == ANARI_FLOAT32_VEC4
         || type == ANARI_FLOAT16_VEC3 || type == ANARI_FLOAT16_VEC4;
}

class PlacedHdri : public PlacedLight
{
 public:
  PlacedHdri(std::shared_ptr<const HdriImage> image,
      float3 up,
      float3 forward,
      float3 color)
      : m_image(std::move(image)), m_color(color)
  {
    const LocalFrame frame = LocalFrame::around(up, forward);
    m_up = frame.z;
    m_forward = frame.x;
    m_right = cross(m_forward, m_up);
  }

  LightSample sample(const float3 &, const float2 &u) const override
  {
    float pdfImage = 0.f;
    const float2 st = m_image->distribution.sample(u, pdfImage);
    const float theta = kPi * st.y;
    const float phi = 2.f * kPi * (st.x - 0.5f);
    const float sinTheta = std::sin(theta);
    LightSample s;
    s.direction = normalize(
        (m_forward * std::cos(phi) + m_right * std::sin(phi)) * sinTheta
        + m_up * std::cos(theta));
    s.distance = kInfinity;
    // Density and radiance from the direction itself, exactly as
    // radianceAlong() finds them, even where rounding crosses a texel edge.
    s.radiance = lookup(s.direction, s.pdf);
    return s;
  }

  float3 radianceAlong(const float3 &,
      const float3 &direction,
      float &distance,
      float &pdf) const override
  {
    distance = kInfinity;
    return lookup(direction, pdf);
  }

  bool isInfinite() const override
  {
    return true;
  }
  float3 power() const override
  {
    // Per unit cross-section: every direction's radiance crosses it.
    return m_color * m_image->averageRadiance * (4.f * kPi);
  }

 private:
  float3 lookup(const float3 &direction, float &pdf) const
  {
    const float cosTheta = clamp(dot(direction, m_up), -1.f, 1.f);
    const float sinTheta = std::sqrt(max(0.f, 1.f - cosTheta * cosTheta));
    const float phi =
        std::atan2(dot(direction, m_right), dot(direction, m_forward));
    const float2 st{phi / (2.f * kPi) + 0.5f, std::acos(cosTheta) / kPi};
    // (s, t) covers the sphere with dw = 2 pi^2 sin(theta) ds dt.
    pdf = sinTheta > 0.f
              ? m_image->distribution.pdf(st) / (2.f * kPi * kPi * sinTheta)
              : 0.f;
    const size_t i = std::min(
        size_t(max(st.x, 0.f) * float(m_image->width)), m_image->width - 1);
    const size_t j = std::min(
        size_t(max(st.y, 0.f) * float(m_image->height)), m_image->height - 1);
    return m_color * m_image->texels[i + j * m_image->width];
  }

  std::shared_ptr<const HdriImage> m_image;
  float3 m_color;
  float3 m_up, m_forward, m_right; // world space, orthonormal
};

} // namespace

Hdri::Hdri(DeviceState &device) : Light(device, "hdri") {}

void Hdri::commitParameters()
{
  Light::commitParameters();
  m_up = readDirection("up");
  m_direction = readDirection("direction");
  if (lengthSquared(cross(m_up, m_direction)) < 1e-12f) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'direction' is parallel to 'up'; the image's center is placed at an "
        "arbitrary direction across 'up'");
  }
  param<std::string>("layout"); // equirectangular, the one layout
  m_scale = readNonNegative("scale");

  const bool set = isSet("radiance");
  m_radianceArray =
      static_cast<Array *>(readObject("radiance", {ANARI_ARRAY2D}));
  if (!m_radianceArray) {
    invalidate(set ? "'radiance' is not an ARRAY2D"
                   : "required parameter 'radiance' (ARRAY2D of FLOAT32_VEC3) "
                     "is not set");
  } else if (!isRadianceElementType(m_radianceArray->elementType())) {
    invalidate("'radiance' has element type %s, not FLOAT32_VEC3",
        anari::toString(m_radianceArray->elementType()));
    m_radianceArray = nullptr;
  } else if (m_radianceArray->size(0) == 0 || m_radianceArray->size(1) == 0) {
    invalidate("'radiance' has no elements");
    m_radianceArray = nullptr;
  }
}

void Hdri::finalize()
{
  m_image.reset(); // released first: never two images at once
  const Array *array = m_radianceArray;
  m_radianceArray = nullptr;
  if (!array || !isValid())
    return;
  try {
    auto image = std::make_shared<HdriImage>();
    image->width = array->size(0);
    image->height = array->size(1);
    const size_t count = image->width * image->height;
    image->texels.resize(count);
    convertToFloat3(
        array->elementType(), array->begin(), count, 0, image->texels.data());

    size_t unusable = 0;
    std::vector<float> weights(count);
    double3 weightedSum{0.0, 0.0, 0.0};
    for (size_t j = 0; j < image->height; j++) {
      // Row j spans theta in [j, j + 1] * pi / height; its texels' solid
      // angle is 2 pi / width * (cos(top) - cos(bottom)).
      const double top = kPiDouble * double(j) / double(image->height);
      const double bottom = kPiDouble * double(j + 1) / double(image->height);
      const double texelSolidAngle = 2.0 * kPiDouble / double(image->width)
                                     * (std::cos(top) - std::cos(bottom));
      for (size_t i = 0; i < image->width; i++) {
        float3 &texel = image->texels[i + j * image->width];
        for (int c = 0; c < 3; c++) {
          if (!(std::isfinite(texel[c]) && texel[c] >= 0.f)) {
            texel[c] = 0.f;
            unusable++;
          }
        }
        texel = texel * m_scale;
        weights[i + j * image->width] =
            float(luminance(texel) * texelSolidAngle);
        weightedSum = weightedSum + vecCast<double>(texel) * texelSolidAngle;
      }
    }
    if (unusable) {
      report(ANARI_SEVERITY_WARNING,
          ANARI_STATUS_INVALID_ARGUMENT,
          "'radiance' has %zu negative or non-finite components; using 0",
          unusable);
    }
    image->distribution =
        Distribution2D(weights.data(), image->width, image->height);
    image->averageRadiance = vecCast<float>(weightedSum / (4.0 * kPiDouble));
    m_image = std::move(image);
  } catch (const std::exception &) {
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_OUT_OF_MEMORY,
        "out of memory building the importance sampling tables of a %llu x "
        "%llu image; the light is invalid",
        (unsigned long long)array->size(0),
        (unsigned long long)array->size(1));
    m_valid = false;
  }
}

std::unique_ptr<PlacedLight> Hdri::place(const mat3x4 &worldFromObject) const
{
  if (!isValid() || !m_image)
    return nullptr;
  auto placed = std::make_unique<PlacedHdri>(m_image,
      transformUnit(worldFromObject, m_up),
      transformUnit(worldFromObject, m_direction),
      m_color);
  placeShared(*placed);
  return placed;
}

} // namespace prism::light
