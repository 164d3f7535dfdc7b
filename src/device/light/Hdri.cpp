#include "Hdri.h"

#include "../array/Array.h"
#include "../array/ElementConversion.h"
#include "Sampling.h"

#include "anari/frontend/type_utility.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>

namespace prism::light {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

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
    return sampleImage(u, kEverySide);
  }

  LightSample sampleFacing(
      const float3 &, const float3 &normal, const float2 &u) const override
  {
    const Mixture mixture = mixtureFacing(normal);
    float2 rest = u;
    const int axis = HdriHemispheres::component(mixture, rest.x);
    if (axis < 0)
      return sampleImage(rest, mixture);
    size_t i = 0, j = 0;
    m_image->hemispheres.sample(m_image->distribution, axis, rest, i, j);
    return sampleTexel(i, j, rest, mixture);
  }

  float3 radianceAlong(const float3 &,
      const float3 &direction,
      float &distance,
      float &pdf) const override
  {
    distance = kInfinity;
    return lookup(direction, kEverySide, pdf);
  }

  float3 radianceAlongFacing(const float3 &,
      const float3 &normal,
      const float3 &direction,
      float &distance,
      float &pdf) const override
  {
    distance = kInfinity;
    return lookup(direction, mixtureFacing(normal), pdf);
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
  using Mixture = HdriHemispheres::Mixture;
  static constexpr Mixture kEverySide = HdriHemispheres::kEverySide;

  Mixture mixtureFacing(const float3 &normal) const
  {
    return m_image->hemispheres.mixture(
        {dot(normal, m_forward), dot(normal, m_right), dot(normal, m_up)});
  }

  // By the image's own distribution.
  LightSample sampleImage(const float2 &u, const Mixture &mixture) const
  {
    float pdfImage = 0.f;
    const float2 cell = m_image->distribution.sample(u, pdfImage);
    // The texel the distribution chose and where in it, uniformly, which
    // becomes a point in proportion to the filtered radiance.
    const float x = cell.x * float(m_image->width);
    const float y = cell.y * float(m_image->height);
    const float i = std::min(std::floor(x), float(m_image->width - 1));
    const float j = std::min(std::floor(y), float(m_image->height - 1));
    return sampleTexel(size_t(i),
        size_t(j),
        {std::clamp(x - i, 0.f, kOneMinusEpsilon),
            std::clamp(y - j, 0.f, kOneMinusEpsilon)},
        mixture);
  }

  // A point of texel (i, j) for uniform `u`, and the mixture's density.
  LightSample sampleTexel(
      size_t i, size_t j, const float2 &u, const Mixture &mixture) const
  {
    const float2 st = m_image->sampleInTexel(int64_t(i), int64_t(j), u);
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
    s.radiance = lookup(s.direction, mixture, s.pdf);
    return s;
  }

  float3 lookup(
      const float3 &direction, const Mixture &mixture, float &pdf) const
  {
    const float cosTheta = clamp(dot(direction, m_up), -1.f, 1.f);
    const float sinTheta = std::sqrt(max(0.f, 1.f - cosTheta * cosTheta));
    const float phi =
        std::atan2(dot(direction, m_right), dot(direction, m_forward));
    const float2 st{phi / (2.f * kPi) + 0.5f, std::acos(cosTheta) / kPi};
    const float3 radiance = m_image->filtered(st);
    // (s, t) covers the sphere with dw = 2 pi^2 sin(theta) ds dt.
    pdf = sinTheta > 0.f
              ? m_image->density(st, radiance) / (2.f * kPi * kPi * sinTheta)
              : 0.f;
    if (mixture[0] < 1.f) {
      const size_t i = st.x > 0.f ? size_t(st.x * float(m_image->width)) : 0;
      const size_t j = st.y > 0.f ? size_t(st.y * float(m_image->height)) : 0;
      pdf *= m_image->hemispheres.factor(mixture, i, j);
    }
    return m_color * radiance;
  }

  std::shared_ptr<const HdriImage> m_image;
  float3 m_color;
  float3 m_up, m_forward, m_right; // world space, orthonormal
};

} // namespace

const float3 &HdriImage::texel(int64_t i, int64_t j) const
{
  const auto w = int64_t(width), h = int64_t(height);
  // Callers reach at most a texel past either side: no division for them.
  i += i < 0 ? w : 0;
  i -= i >= w ? w : 0;
  if (i < 0 || i >= w)
    i = (i % w + w) % w;
  j = std::clamp<int64_t>(j, 0, h - 1);
  return texels[size_t(i + j * w)];
}

float3 HdriImage::filtered(const float2 &st) const
{
  // Texel centres sit at half-integer coordinates; (s, t) strays from
  // [0, 1] by rounding only (max after min: NaN gives -1).
  const float x =
      std::max(-1.f, std::min(st.x * float(width) - 0.5f, float(width)));
  const float y =
      std::max(-1.f, std::min(st.y * float(height) - 0.5f, float(height)));
  // Truncating a positive number floors it (no floor instruction in
  // baseline x86-64).
  const auto i = int64_t(x + 1.f) - 1, j = int64_t(y + 1.f) - 1;
  const float fx = x - float(i), fy = y - float(j);
  return (texel(i, j) * (1.f - fx) + texel(i + 1, j) * fx) * (1.f - fy)
         + (texel(i, j + 1) * (1.f - fx) + texel(i + 1, j + 1) * fx) * fy;
}

float3 HdriImage::texelAverage(int64_t i, int64_t j) const
{
  // Over the texel, the filter weighs it 3/4 and each neighbour along an
  // axis 1/8 (a quarter of each half of the texel), per axis.
  constexpr float kWeights[3] = {0.125f, 0.75f, 0.125f};
  float3 sum{0.f, 0.f, 0.f};
  for (int b = 0; b < 3; b++)
    for (int a = 0; a < 3; a++)
      sum = sum + texel(i + a - 1, j + b - 1) * (kWeights[a] * kWeights[b]);
  return sum;
}

namespace {

// Filtered luminance at texel (i, j)'s corners, edge midpoints and centre:
// grid[b][a] at (a / 2, b / 2) in the texel. Between texel centres the
// filter is linear, so a corner is the mean of the four texels around it
// and an edge's midpoint the mean of the two on either side.
void luminanceGrid(
    const HdriImage &image, int64_t i, int64_t j, float grid[3][3])
{
  float l[3][3]; // the texel and its eight neighbours
  for (int b = 0; b < 3; b++)
    for (int a = 0; a < 3; a++)
      l[b][a] = luminance(image.texel(i + a - 1, j + b - 1));
  // Along each axis: 0 the texel's edge before it, 1 its centre, 2 after.
  constexpr int kFirst[3] = {0, 1, 1}, kLast[3] = {1, 1, 2};
  for (int b = 0; b < 3; b++) {
    for (int a = 0; a < 3; a++) {
      grid[b][a] = 0.25f
                   * (l[kFirst[b]][kFirst[a]] + l[kFirst[b]][kLast[a]]
                       + l[kLast[b]][kFirst[a]] + l[kLast[b]][kLast[a]]);
    }
  }
}

// x in [0, 1] with density in proportion to (1 - x) a + x b (a, b >= 0).
float sampleLinear(float u, float a, float b)
{
  if (!(std::abs(a - b) > 1e-6f * (a + b)))
    return u;
  const float x =
      (a - std::sqrt(std::max(0.f, (1.f - u) * a * a + u * b * b))) / (a - b);
  return std::clamp(x, 0.f, 1.f);
}

} // namespace

float2 HdriImage::sampleInTexel(int64_t i, int64_t j, float2 u) const
{
  float grid[3][3];
  luminanceGrid(*this, i, j, grid);
  // Each quarter of the texel lies in one bilinear patch: choose one by
  // its average, then a point in it by the patch's density.
  float quarter[4], total = 0.f;
  for (int q = 0; q < 4; q++) {
    const int a = q & 1, b = q >> 1;
    quarter[q] =
        grid[b][a] + grid[b][a + 1] + grid[b + 1][a] + grid[b + 1][a + 1];
    total += quarter[q];
  }
  if (!(total > 0.f))
    return u;
  float target = u.x * total;
  int q = 0;
  while (q < 3 && (target >= quarter[q] || !(quarter[q] > 0.f))) {
    target -= quarter[q];
    q++;
  }
  const float ux = std::clamp(target / quarter[q], 0.f, kOneMinusEpsilon);
  const int a = q & 1, b = q >> 1;
  const float c00 = grid[b][a], c10 = grid[b][a + 1];
  const float c01 = grid[b + 1][a], c11 = grid[b + 1][a + 1];
  const float x = sampleLinear(ux, c00 + c01, c10 + c11);
  const float y =
      sampleLinear(u.y, c00 + (c10 - c00) * x, c01 + (c11 - c01) * x);
  return {(float(i) + 0.5f * (float(a) + x)) / float(width),
      (float(j) + 0.5f * (float(b) + y)) / float(height)};
}

float HdriImage::density(const float2 &st, const float3 &radiance) const
{
  const double meanWeight = distribution.integral();
  if (!(meanWeight > 0.0))
    return 1.f; // a black image: sampled uniformly
  const float y = st.y * float(height);
  const size_t j = y > 0.f ? std::min(size_t(y), height - 1) : 0;
  return float(double(luminance(radiance)) * texelSolidAngle[j] / meanWeight);
}

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
    for (float3 &texel : image->texels) {
      texel = texel * m_scale;
      for (int c = 0; c < 3; c++) {
        // Scaled first: a finite texel the scale overflows is unusable too.
        if (!(std::isfinite(texel[c]) && texel[c] >= 0.f)) {
          texel[c] = 0.f;
          unusable++;
        }
      }
    }
    std::vector<float> weights(count);
    image->texelSolidAngle.resize(image->height);
    double3 weightedSum{0.0, 0.0, 0.0};
    for (size_t j = 0; j < image->height; j++) {
      // Row j spans theta in [j, j + 1] * pi / height; its texels' solid
      // angle is 2 pi / width * (cos(top) - cos(bottom)).
      const double top = kPiDouble * double(j) / double(image->height);
      const double bottom = kPiDouble * double(j + 1) / double(image->height);
      const float texelSolidAngle = float(2.0 * kPiDouble / double(image->width)
                                          * (std::cos(top) - std::cos(bottom)));
      image->texelSolidAngle[j] = texelSolidAngle;
      for (size_t i = 0; i < image->width; i++) {
        const float3 average = image->texelAverage(int64_t(i), int64_t(j));
        weights[i + j * image->width] = luminance(average) * texelSolidAngle;
        weightedSum =
            weightedSum + vecCast<double>(average) * double(texelSolidAngle);
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
    image->hemispheres = HdriHemispheres(weights, image->width, image->height);
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
