#include "Bsdf.h"

#include "AlbedoTables.h"
#include "Fresnel.h"
#include "GgxLobe.h"
#include "Microfacet.h"
#include "Sampling.h"

#include <cmath>
#include <numbers>

namespace prism {

namespace {

constexpr float kInvPi = std::numbers::inv_pi_v<float>;

// Below this GGX width a lobe is treated as a perfect mirror / refractor:
// roughness < 0.01, where float half vectors no longer resolve the peak.
constexpr float kDeltaAlpha = 1e-4f;

// Clearcoat is a fixed ior 1.5 layer (KHR_materials_clearcoat).
constexpr float kCoatF0 = 0.04f;

// Whether the viewer's direction `wo` can be shaded (finite, off the
// surface's plane), and on which side it is: -1 behind the shading normal.
bool viewerSide(float3 wo, float &sign)
{
  if (!(wo.z != 0.f) || !std::isfinite(wo.x + wo.y + wo.z))
    return false;
  sign = wo.z < 0.f ? -1.f : 1.f;
  return true;
}

float mean(float3 v)
{
  return (v.x + v.y + v.z) * (1.f / 3.f);
}

float finiteOr(float value, float fallback)
{
  return std::isfinite(value) ? value : fallback;
}

float2 finiteOr(float2 value, float2 fallback)
{
  return {finiteOr(value.x, fallback.x), finiteOr(value.y, fallback.y)};
}

float3 finiteOr(float3 value, float3 fallback)
{
  return {finiteOr(value.x, fallback.x),
      finiteOr(value.y, fallback.y),
      finiteOr(value.z, fallback.z)};
}

float unitClamp(float value, float fallback)
{
  return clamp(finiteOr(value, fallback), 0.f, 1.f);
}

// Kulla & Conty's colour of the multiple-scattering lobe: the series of
// bounces between microfacets, each reflecting the average Fresnel.
float multiScatterFresnel(float averageFresnel, float averageAlbedo)
{
  return averageFresnel * averageFresnel * averageAlbedo
         / (1.f - averageFresnel * (1.f - averageAlbedo));
}
float3 multiScatterFresnel(float3 averageFresnel, float averageAlbedo)
{
  return {multiScatterFresnel(averageFresnel.x, averageAlbedo),
      multiScatterFresnel(averageFresnel.y, averageAlbedo),
      multiScatterFresnel(averageFresnel.z, averageAlbedo)};
}

// Cosine-weighted hemispherical average of Schlick's F: f0 + (f90 - f0)/21.
float3 averageSchlick(float3 f0, float f90)
{
  return f0 * (20.f / 21.f) + f90 * (1.f / 21.f);
}

// Walter et al. 2007's microfacet transmission between indices etaO (wo's
// side, wo.z > 0) and etaI (wi's side, wi.z < 0), without the Fresnel
// factor: f, the pdf of sampling wi through visible normals, and cos(wo, h).
struct Refraction
{
  float btdf{0.f}, pdf{0.f}, cosOH{0.f};
};

Refraction microfacetRefraction(
    float3 wo, float3 wi, float etaO, float etaI, const GgxLobe &lobe)
{
  Refraction r;
  // The generalised half vector, on the side of the normal.
  float3 h = wo * etaO + wi * etaI;
  const float lengthSquared = dot(h, h);
  if (!(lengthSquared > 1e-12f))
    return r;
  h = h * (1.f / std::sqrt(lengthSquared));
  if (h.z < 0.f)
    h = -h;
  const float cosOH = dot(wo, h);
  const float cosIH = dot(wi, h);
  // The facet must face wo and have wi behind it.
  if (cosOH <= 0.f || cosIH >= 0.f)
    return r;
  const float denominator = etaO * cosOH + etaI * cosIH;
  const float denominator2 = denominator * denominator;
  if (!(denominator2 > 1e-12f))
    return r;
  const float d = lobe.D(h);
  r.btdf = cosOH * -cosIH / (wo.z * -wi.z) * etaO * etaO * d * lobe.G2(wo, wi)
           / denominator2;
  r.pdf = lobe.G1(wo) * cosOH * d / wo.z * etaI * etaI * -cosIH / denominator2;
  r.cosOH = cosOH;
  return r;
}

float3 mirror(float3 w)
{
  return {-w.x, -w.y, w.z};
}

// The cosine at which Schlick's weight equals the lobe's average of it,
// (1 - c)^5 = schlick / total: evaluating a non-Schlick Fresnel (the thin
// film) there estimates its lobe average, exactly so for Schlick.
float effectiveCos(float total, float schlick)
{
  if (!(total > 0.f))
    return 1.f;
  return 1.f - std::pow(clamp(schlick / total, 0.f, 1.f), 0.2f);
}

} // namespace

// Everything that depends on wo only, shared by eval, pdf and sample.
struct Bsdf::Context
{
  bool valid{false};
  bool inside{false};       // viewer inside the volume
  float sign{1.f};          // local z of the caller's frame over ours
  float3 wo{0.f, 0.f, 1.f}; // in our frame: wo.z > 0
  float cosO{1.f};
  Albedo specularO{1.f, 0.f, 1.f};
  float dielectricO{0.f}; // albedo of the dielectric specular layer at wo
  float coatO{0.f};       // albedo of the clearcoat at wo, weight included
  float sheenO{0.f};      // albedo of the sheen at wo, max over channels
  float probability[kLobeCount]{};
};

Bsdf::Bsdf(const BsdfInputs &in)
{
  m_baseColor = clamp(finiteOr(in.baseColor, {0.f, 0.f, 0.f}), 0.f, 1.f);
  // The most common BSDF by far (every matte surface): nothing but Lambert,
  // decided before any of the layers' set-up.
  if (in.metallic == 0.f && in.specular == 0.f && in.transmission == 0.f
      && in.clearcoat == 0.f && in.iridescence == 0.f && in.sheenColor.x == 0.f
      && in.sheenColor.y == 0.f && in.sheenColor.z == 0.f) {
    m_metallic = 0.f;
    m_lambertOnly = true;
    m_hasNonDeltaLobes = true;
    return;
  }
  m_metallic = unitClamp(in.metallic, 0.f);
  m_roughness = unitClamp(in.roughness, 1.f);
  m_alpha = m_roughness * m_roughness;
  m_lobe = GgxLobe(m_roughness,
      unitClamp(in.anisotropy, 0.f),
      finiteOr(in.anisotropyDirection, float2{1.f, 0.f}));
  m_specularDelta = m_alpha < kDeltaAlpha && !m_lobe.anisotropic();

  // KHR_materials_specular: f0 from the ior, tinted and clamped, then
  // weighted; f90 is the weight alone.
  const float specular = unitClamp(in.specular, 0.f);
  float ior = finiteOr(in.ior, 1.5f);
  if (!(ior > 0.f))
    ior = 1.5f;
  const float3 specularColor =
      max(finiteOr(in.specularColor, {1.f, 1.f, 1.f}), float3{0.f, 0.f, 0.f});
  m_dielectricF0 =
      min(specularColor * f0FromIor(ior), float3{1.f, 1.f, 1.f}) * specular;
  m_dielectricF90 = specular;
  m_dielectricF0Max = maxComponent(m_dielectricF0);

  const float transmission = unitClamp(in.transmission, 0.f);
  m_transmissionWeight = (1.f - m_metallic) * transmission;
  const float thickness = finiteOr(in.thickness, 0.f);
  m_volume = m_transmissionWeight > 0.f && thickness > 0.f;
  // Refraction through an index step of ~0 has no defined half vector.
  if (m_volume && std::abs(ior - 1.f) < 1e-3f)
    ior = ior < 1.f ? 0.999f : 1.001f;
  m_ior = ior;

  m_iridescence = unitClamp(in.iridescence, 0.f);
  m_filmIor = finiteOr(in.iridescenceIor, 1.3f);
  if (!(m_filmIor > 0.f))
    m_filmIor = 1.3f;
  m_filmThickness = max(finiteOr(in.iridescenceThickness, 0.f), 0.f);

  m_sheenColor = clamp(finiteOr(in.sheenColor, {0.f, 0.f, 0.f}), 0.f, 1.f);
  m_sheenMax = maxComponent(m_sheenColor);
  m_sheenRoughness = unitClamp(in.sheenRoughness, 0.f);
  m_sheenAlpha = charlieAlpha(m_sheenRoughness);

  m_clearcoat = unitClamp(in.clearcoat, 0.f);
  m_coatRoughness = unitClamp(in.clearcoatRoughness, 0.f);
  m_coatAlpha = m_coatRoughness * m_coatRoughness;
  m_coatDelta = m_coatAlpha < kDeltaAlpha;
  const float3 coatNormal = finiteOr(in.clearcoatNormal, float3{0.f, 0.f, 1.f});
  if (m_clearcoat > 0.f && coatNormal.z > 0.f
      && (coatNormal.x != 0.f || coatNormal.y != 0.f)) {
    m_coatZ = normalize(coatNormal);
    orthonormalBasis(m_coatZ, m_coatX, m_coatY);
    m_coatTilted = true;
  }

  const bool specularOff = m_metallic == 0.f && m_dielectricF90 == 0.f
                           && m_dielectricF0Max == 0.f && m_iridescence == 0.f;
  m_lambertOnly = specularOff && m_transmissionWeight == 0.f
                  && m_sheenMax == 0.f && m_clearcoat == 0.f;

  const bool diffuse = m_transmissionWeight < 1.f - m_metallic;
  m_hasNonDeltaLobes = diffuse || !m_specularDelta || m_sheenMax > 0.f
                       || (m_clearcoat > 0.f && !m_coatDelta);
  if (m_lambertOnly)
    return;

  // Multiple scattering: Kulla & Conty's lobe, coloured per metallic mix.
  const GgxAlbedo average = m_specularDelta
                                ? mirrorAlbedo(1.f)
                                : ggxAlbedo(1.f, m_lobe.albedoRoughness());
  m_ggxAverage = average.average;
  const float3 dielectricAverageF =
      averageSchlick(m_dielectricF0, m_dielectricF90);
  const float3 metalAverageF = averageSchlick(m_baseColor, 1.f);
  m_multiFresnel = lerp(multiScatterFresnel(dielectricAverageF, m_ggxAverage),
      multiScatterFresnel(metalAverageF, m_ggxAverage),
      m_metallic);
  m_dielectricMultiFresnel =
      multiScatterFresnel(maxComponent(dielectricAverageF), m_ggxAverage);

  // Average of dielectricAlbedo(): exact for Schlick (linear in the table
  // averages). With iridescence, the average of iridescentAlbedo()'s Schlick
  // term is a lower bound of its true average, which can only make the
  // diffuse lose (a little) energy, never gain it, and costs one film
  // evaluation instead of a quadrature per hit.
  float average0 =
      m_dielectricF0Max * (average.average - average.schlickAverage)
      + m_dielectricF90 * average.schlickAverage;
  if (m_iridescence > 0.f) {
    m_filmNormalF0Max = maxComponent(
        fresnelThinFilm(1.f, m_filmIor, m_filmThickness, m_dielectricF0));
    const float iridescent =
        m_filmNormalF0Max * (average.average - average.schlickAverage)
        + average.schlickAverage;
    average0 = lerp(average0, iridescent, m_iridescence);
  }
  m_dielectricAlbedoAverage =
      min(1.f, average0 + m_dielectricMultiFresnel * (1.f - m_ggxAverage));
}

Bsdf::Albedo Bsdf::specularAlbedo(float cosTheta) const
{
  const GgxAlbedo a = m_specularDelta
                          ? mirrorAlbedo(cosTheta)
                          : ggxAlbedo(cosTheta, m_lobe.albedoRoughness());
  return {a.total, a.schlick, a.meanCos};
}

// Albedo of the dielectric specular lobe (single + multiple scattering), the
// max over channels: what the layers beneath it (diffuse, transmission) are
// scaled against, as KHR_materials_specular's max_value does.
float Bsdf::dielectricAlbedo(const Albedo &a) const
{
  float single =
      m_dielectricF0Max * (a.total - a.schlick) + m_dielectricF90 * a.schlick;
  if (m_iridescence > 0.f)
    single = lerp(single, iridescentAlbedo(a), m_iridescence);
  return min(1.f, single + m_dielectricMultiFresnel * (1.f - a.total));
}

// The thin film's Fresnel is not Schlick's, so the tables do not give its
// lobe albedo. The largest of three estimates (the film's curve at the mean
// cosine, at Schlick's effective cosine, and Schlick's curve from the film's
// normal reflectance) is never more than 0.3% below the true albedo
// (measured over roughness, angle and thickness), so the layers beneath gain
// no energy.
float Bsdf::iridescentAlbedo(const Albedo &a) const
{
  const float3 atMean =
      fresnelThinFilm(a.meanCos, m_filmIor, m_filmThickness, m_dielectricF0);
  const float3 atEffective = fresnelThinFilm(effectiveCos(a.total, a.schlick),
      m_filmIor,
      m_filmThickness,
      m_dielectricF0);
  const float schlick = m_filmNormalF0Max * (a.total - a.schlick) + a.schlick;
  return max(
      a.total * max(maxComponent(atMean), maxComponent(atEffective)), schlick);
}

float3 Bsdf::toCoat(const Context &c, float3 w) const
{
  if (!m_coatTilted || c.sign < 0.f)
    return w;
  return {dot(w, m_coatX), dot(w, m_coatY), dot(w, m_coatZ)};
}

float3 Bsdf::fromCoat(const Context &c, float3 w) const
{
  if (!m_coatTilted || c.sign < 0.f)
    return w;
  return m_coatX * w.x + m_coatY * w.y + m_coatZ * w.z;
}

float Bsdf::coatAlbedo(float cosTheta) const
{
  // A coat facing away from the direction reflects nothing of it.
  if (!(cosTheta > 0.f))
    return 0.f;
  if (m_clearcoat == 0.f)
    return 0.f;
  const GgxAlbedo a = m_coatDelta ? mirrorAlbedo(cosTheta)
                                  : ggxAlbedo(cosTheta, m_coatRoughness);
  return m_clearcoat * (kCoatF0 * (a.total - a.schlick) + a.schlick);
}

float Bsdf::sheenLayerAlbedo(float cosTheta) const
{
  if (m_sheenMax == 0.f)
    return 0.f;
  return m_sheenMax * min(1.f, sheenAlbedo(cosTheta, m_sheenRoughness));
}

// Schlick's curve for the dielectric interface seen from the side of
// relative index eta = n(wo's side) / n(far side): from the dense side it
// must be taken at the transmitted angle, and beyond the critical angle all
// light reflects.
float3 Bsdf::interfaceFresnel(float cosTheta, float eta) const
{
  float c = cosTheta;
  if (eta > 1.f) {
    const float sin2T = eta * eta * max(0.f, 1.f - c * c);
    if (sin2T >= 1.f)
      return {1.f, 1.f, 1.f};
    c = std::sqrt(1.f - sin2T);
  }
  const float3 f90{m_dielectricF90, m_dielectricF90, m_dielectricF90};
  return fresnelSchlick(m_dielectricF0, f90, c);
}

// Seen from outside; only a volume of ior < 1 has total internal reflection
// there.
float3 Bsdf::dielectricFresnel(float cosTheta) const
{
  const float3 schlick =
      interfaceFresnel(cosTheta, m_volume ? 1.f / m_ior : 1.f);
  if (m_iridescence == 0.f)
    return schlick;
  return lerp(schlick,
      fresnelThinFilm(cosTheta, m_filmIor, m_filmThickness, m_dielectricF0),
      m_iridescence);
}

// glTF's material = mix(dielectric, metal, metallic) collapses to one GGX
// lobe whose Fresnel is the mix of the two Fresnels.
float3 Bsdf::specularFresnel(float cosTheta) const
{
  const float3 one{1.f, 1.f, 1.f};
  float3 metal = fresnelSchlick(m_baseColor, one, cosTheta);
  if (m_iridescence > 0.f) {
    metal = lerp(metal,
        fresnelThinFilm(cosTheta, m_filmIor, m_filmThickness, m_baseColor),
        m_iridescence);
  }
  return lerp(dielectricFresnel(cosTheta), metal, m_metallic);
}

Bsdf::Context Bsdf::prepare(float3 wo) const
{
  // Layered BSDFs only: Lambert alone needs none of this.
  Context c;
  if (!viewerSide(wo, c.sign))
    return c;
  c.wo = {wo.x, wo.y, std::abs(wo.z)};
  c.cosO = c.wo.z;
  c.inside = c.sign < 0.f && m_volume;
  c.valid = true;
  c.specularO = specularAlbedo(c.cosO);
  if (c.inside)
    return c;
  c.dielectricO = dielectricAlbedo(c.specularO);
  c.coatO = coatAlbedo(toCoat(c, c.wo).z);
  c.sheenO = sheenLayerAlbedo(c.cosO);

  // Lobe selection in proportion to each lobe's albedo estimate at wo.
  float w[kLobeCount] = {};
  w[kCoat] = c.coatO;
  const float belowCoat = 1.f - c.coatO;
  if (m_sheenMax > 0.f) {
    w[kSheen] = belowCoat * mean(m_sheenColor)
                * min(1.f, sheenAlbedo(c.cosO, m_sheenRoughness));
  }
  const float base = belowCoat * (1.f - c.sheenO);
  const float e = c.specularO.total;
  const float3 f0 = lerp(m_dielectricF0, m_baseColor, m_metallic);
  const float f90 = lerp(m_dielectricF90, 1.f, m_metallic);
  float3 single = f0 * (e - c.specularO.schlick) + f90 * c.specularO.schlick;
  if (m_iridescence > 0.f)
    single =
        lerp(single, specularFresnel(c.specularO.meanCos) * e, m_iridescence);
  w[kSpecular] = base * mean(single);
  w[kSpecularMulti] = base * mean(m_multiFresnel) * (1.f - e);
  const float under = base * mean(m_baseColor) * (1.f - c.dielectricO);
  w[kDiffuse] = under * max(0.f, 1.f - m_metallic - m_transmissionWeight);
  const float transmission = under * m_transmissionWeight;
  if (!m_volume && !m_specularDelta) {
    w[kTransmission] = transmission * e;
    w[kTransmissionMulti] = transmission * (1.f - e);
  } else {
    w[kTransmission] = transmission;
  }

  float total = 0.f;
  for (float weight : w)
    total += weight;
  if (!(total > 0.f)) {
    c.valid = false;
    return c;
  }
  for (int k = 0; k < kLobeCount; k++)
    c.probability[k] = w[k] / total;
  return c;
}

void Bsdf::evaluate(const Context &c, float3 wiIn, float3 &f, float &pdf) const
{
  f = {0.f, 0.f, 0.f};
  pdf = 0.f;
  if (!c.valid)
    return;
  const float3 wi{wiIn.x, wiIn.y, wiIn.z * c.sign};
  if (!(wi.z != 0.f) || !std::isfinite(wi.x + wi.y + wi.z))
    return;
  if (c.inside) {
    evaluateInterior(c, wi, f, pdf);
    return;
  }
  const float3 wo = c.wo;
  const float cosO = c.cosO;

  if (wi.z > 0.f) {
    const float cosI = wi.z;
    const float3 h = normalize(wo + wi);
    const float cosOH = dot(wo, h);
    // The coat in its own frame (the base's unless clearcoatNormal tilts
    // it).
    const float3 woC = toCoat(c, wo), wiC = toCoat(c, wi);
    if (m_clearcoat > 0.f && !m_coatDelta && woC.z > 0.f && wiC.z > 0.f) {
      const float3 hC = normalize(woC + wiC);
      const float d = ggxD(hC, m_coatAlpha);
      const float fresnel = fresnelSchlick(kCoatF0, 1.f, dot(woC, hC));
      // Dividing by the larger of each direction's two cosines keeps a
      // tilted coat reciprocal and within its own albedo (for an untilted
      // coat the two are equal).
      const float value = m_clearcoat * fresnel * d
                          * ggxG2(woC, wiC, m_coatAlpha)
                          / (4.f * max(cosO, woC.z) * max(cosI, wiC.z));
      f += float3{value, value, value};
      pdf += c.probability[kCoat] * ggxG1(woC, m_coatAlpha) * d / (4.f * woC.z);
    }
    // Light under the coat crosses it twice: reciprocal albedo scaling.
    const float coatScale = (1.f - c.coatO) * (1.f - coatAlbedo(wiC.z));
    if (m_sheenMax > 0.f) {
      // Dividing by the larger albedo (when above 1) keeps narrow sheen
      // from creating energy at grazing angles, and keeps it reciprocal.
      const float normalization = max(1.f,
          max(sheenAlbedo(cosO, m_sheenRoughness),
              sheenAlbedo(cosI, m_sheenRoughness)));
      f += m_sheenColor
           * (coatScale * charlieD(h, m_sheenAlpha)
               * charlieVisibility(cosO, cosI, m_sheenAlpha) / normalization);
      pdf += c.probability[kSheen] * uniformHemispherePdf();
    }
    // KHR_materials_sheen's albedo scaling, min() keeping it reciprocal.
    const float scale =
        coatScale * min(1.f - c.sheenO, 1.f - sheenLayerAlbedo(cosI));
    const Albedo specularI = specularAlbedo(cosI);
    if (!m_specularDelta) {
      const float d = m_lobe.D(h);
      f += specularFresnel(cosOH)
           * (scale * d * m_lobe.G2(wo, wi) / (4.f * cosO * cosI));
      pdf += c.probability[kSpecular] * m_lobe.G1(wo) * d / (4.f * cosO);
      if (m_ggxAverage < 1.f) {
        // Kulla & Conty: (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg))
        // integrates to exactly the energy single scattering lost.
        const float multi = (1.f - c.specularO.total) * (1.f - specularI.total)
                            * kInvPi / (1.f - m_ggxAverage);
        f += m_multiFresnel * (scale * multi);
      }
      pdf += c.probability[kSpecularMulti] * cosI * kInvPi;
    }
    const float diffuseWeight =
        max(0.f, 1.f - m_metallic - m_transmissionWeight);
    if (diffuseWeight > 0.f) {
      // The diffuse sees what the specular layer leaves, on the way in and
      // out: Kulla & Conty's reciprocal albedo scaling, exact in energy.
      const float remaining = 1.f - m_dielectricAlbedoAverage;
      if (remaining > 1e-6f) {
        const float layer = (1.f - c.dielectricO)
                            * (1.f - dielectricAlbedo(specularI)) / remaining;
        f += m_baseColor * (scale * diffuseWeight * layer * kInvPi);
      }
      pdf += c.probability[kDiffuse] * cosI * kInvPi;
    }
    return;
  }

  // Transmission: through the coat and sheen once, then what the specular
  // layer lets through.
  if (m_transmissionWeight == 0.f || m_specularDelta)
    return;
  const float scale = (1.f - c.coatO) * (1.f - c.sheenO) * m_transmissionWeight;
  if (!m_volume) {
    // Thin-walled: the reflection lobe mirrored through the sheet, so the
    // light goes straight on, blurred by roughness (KHR_materials_
    // transmission); made energy-preserving by the multiple-scattering term.
    const float3 wr{wi.x, wi.y, -wi.z};
    const float cosR = wr.z;
    const float3 h = normalize(wo + wr);
    const float d = m_lobe.D(h);
    float unit = d * m_lobe.G2(wo, wr) / (4.f * cosO * cosR);
    if (m_ggxAverage < 1.f) {
      unit += (1.f - c.specularO.total) * (1.f - specularAlbedo(cosR).total)
              * kInvPi / (1.f - m_ggxAverage);
    }
    f = m_baseColor * (scale * (1.f - c.dielectricO) * unit);
    pdf = c.probability[kTransmission] * m_lobe.G1(wo) * d / (4.f * cosO)
          + c.probability[kTransmissionMulti] * cosR * kInvPi;
    return;
  }
  // Entering the volume: each microfacet splits F / 1 - F, tinted by
  // baseColor once on the way in (never on the way out).
  const Refraction r = microfacetRefraction(wo, wi, 1.f, m_ior, m_lobe);
  if (r.pdf == 0.f)
    return;
  const float fresnel = maxComponent(dielectricFresnel(r.cosOH));
  f = m_baseColor * (scale * (1.f - fresnel) * r.btdf);
  pdf = c.probability[kTransmission] * r.pdf;
}

// Inside the volume only the bare dielectric interface remains: reflection F
// and refraction 1 - F per microfacet, chosen with probability max F.
void Bsdf::evaluateInterior(
    const Context &c, float3 wi, float3 &f, float &pdf) const
{
  if (m_specularDelta)
    return;
  const float3 wo = c.wo;
  if (wi.z > 0.f) {
    const float3 h = normalize(wo + wi);
    const float3 fresnel = interfaceFresnel(dot(wo, h), m_ior);
    const float d = m_lobe.D(h);
    f = fresnel * (d * m_lobe.G2(wo, wi) / (4.f * c.cosO * wi.z));
    pdf = maxComponent(fresnel) * m_lobe.G1(wo) * d / (4.f * c.cosO);
    return;
  }
  const Refraction r = microfacetRefraction(wo, wi, m_ior, 1.f, m_lobe);
  if (r.pdf == 0.f)
    return;
  const float transmitted =
      1.f - maxComponent(interfaceFresnel(r.cosOH, m_ior));
  f = float3{1.f, 1.f, 1.f} * (transmitted * r.btdf);
  pdf = transmitted * r.pdf;
}

float3 Bsdf::eval(float3 wo, float3 wi) const
{
  float3 f;
  float p;
  evalAndPdf(wo, wi, f, p);
  return f;
}

float Bsdf::pdf(float3 wo, float3 wi) const
{
  float3 f;
  float p;
  evalAndPdf(wo, wi, f, p);
  return p;
}

void Bsdf::evalAndPdf(float3 wo, float3 wi, float3 &f, float &pdf) const
{
  if (m_lambertOnly) {
    evaluateLambert(wo, wi, f, pdf);
    return;
  }
  evaluate(prepare(wo), wi, f, pdf);
}

// A Lambert-only BSDF, the most common by far, without the layers'
// context.
void Bsdf::evaluateLambert(float3 wo, float3 wiIn, float3 &f, float &pdf) const
{
  f = {0.f, 0.f, 0.f};
  pdf = 0.f;
  float sign = 1.f;
  if (!viewerSide(wo, sign))
    return;
  const float3 wi{wiIn.x, wiIn.y, wiIn.z * sign};
  if (!(wi.z > 0.f) || !std::isfinite(wi.x + wi.y + wi.z))
    return;
  f = m_baseColor * kInvPi;
  pdf = wi.z * kInvPi;
}

namespace {

// A delta sample in the caller's frame: f = reflectance / |cos| so that
// f |cos| / pdf is reflectance / probability.
BsdfSample deltaSample(float3 wi,
    float sign,
    float3 reflectance,
    float probability,
    float relativeIor)
{
  BsdfSample s;
  const float cosI = std::abs(wi.z);
  if (!(probability > 0.f) || !(cosI > 0.f) || maxComponent(reflectance) <= 0.f)
    return s;
  s.wi = {wi.x, wi.y, wi.z * sign};
  s.f = reflectance * (1.f / cosI);
  s.pdf = probability;
  s.weight = reflectance * (1.f / probability);
  s.relativeIor = relativeIor;
  s.flags = kBsdfDelta | (wi.z > 0.f ? kBsdfReflection : kBsdfTransmission);
  return s;
}

} // namespace

BsdfSample Bsdf::sampleInterior(const Context &c, float2 u, float uLobe) const
{
  const float3 wo = c.wo;
  if (m_specularDelta) {
    const float3 fresnel = interfaceFresnel(c.cosO, m_ior);
    const float reflect = maxComponent(fresnel);
    if (uLobe < reflect)
      return deltaSample(mirror(wo), c.sign, fresnel, reflect, 1.f);
    float3 wi;
    if (!refractDirection(wo, {0.f, 0.f, 1.f}, m_ior, wi))
      return {};
    // Leaving the medium, radiance scales by ior^2.
    const float3 transmitted =
        float3{1.f, 1.f, 1.f} * ((1.f - reflect) * m_ior * m_ior);
    return deltaSample(wi, c.sign, transmitted, 1.f - reflect, 1.f / m_ior);
  }
  const float3 h = m_lobe.sampleVisibleNormal(wo, u);
  const float reflect = maxComponent(interfaceFresnel(dot(wo, h), m_ior));
  float3 wi;
  if (uLobe < reflect) {
    wi = reflectDirection(wo, h);
    if (wi.z <= 0.f)
      return {};
  } else if (!refractDirection(wo, h, m_ior, wi) || wi.z >= 0.f) {
    return {};
  }
  BsdfSample s;
  float3 f;
  float pdf;
  evaluateInterior(c, wi, f, pdf);
  if (!(pdf > 0.f) || maxComponent(f) <= 0.f)
    return s;
  s.wi = {wi.x, wi.y, wi.z * c.sign};
  s.f = f;
  s.pdf = pdf;
  s.weight = f * (std::abs(wi.z) / pdf);
  s.relativeIor = wi.z > 0.f ? 1.f : 1.f / m_ior;
  s.flags = wi.z > 0.f ? kBsdfReflection : kBsdfTransmission;
  return s;
}

BsdfSample Bsdf::sample(float3 woIn, float2 u, float uLobe) const
{
  if (m_lambertOnly)
    return sampleLambert(woIn, u);
  const Context c = prepare(woIn);
  if (!c.valid)
    return {};
  if (c.inside)
    return sampleInterior(c, u, uLobe);
  const int lobe = chooseLobe(c, uLobe);
  float3 wi{0.f, 0.f, 1.f};
  BsdfSample whole;
  if (!sampleDirection(c, lobe, u, wi, whole))
    return whole;
  return sampleFromDirection(c, lobe, wi);
}

BsdfSample Bsdf::sampleLambert(float3 woIn, float2 u) const
{
  float sign = 1.f;
  if (!viewerSide(woIn, sign))
    return {};
  // One lobe sampled exactly by its density: f cos / pdf = baseColor.
  const float3 wi = sampleCosineHemisphere(u);
  if (!(wi.z > 0.f) || maxComponent(m_baseColor) <= 0.f)
    return {};
  BsdfSample s;
  s.wi = {wi.x, wi.y, wi.z * sign};
  s.f = m_baseColor * kInvPi;
  s.pdf = wi.z * kInvPi;
  s.weight = m_baseColor;
  s.relativeIor = 1.f;
  s.flags = kBsdfReflection;
  return s;
}

int Bsdf::chooseLobe(const Context &c, float uLobe) const
{
  int lobe = kLobeCount - 1;
  float cumulative = 0.f;
  for (int k = 0; k < kLobeCount; k++) {
    cumulative += c.probability[k];
    if (uLobe < cumulative && c.probability[k] > 0.f) {
      lobe = k;
      break;
    }
  }
  // Rounding can leave uLobe above the sum: take the last possible lobe.
  while (lobe > 0 && c.probability[lobe] == 0.f)
    lobe--;
  return lobe;
}

// A direction from `lobe` into wi (our frame), to be evaluated over every
// lobe; or false, with `whole` the whole sample: a delta lobe's, or none.
bool Bsdf::sampleDirection(
    const Context &c, int lobe, float2 u, float3 &wi, BsdfSample &whole) const
{
  const float3 wo = c.wo;
  const float probability = c.probability[lobe];
  switch (lobe) {
  case kCoat: {
    const float3 woC = toCoat(c, wo);
    if (m_coatDelta) {
      const float3 mirrored = fromCoat(c, mirror(woC));
      if (!(mirrored.z > 0.f))
        return false; // the coat reflects it below the surface
      const float reflectance =
          m_clearcoat * fresnelSchlick(kCoatF0, 1.f, woC.z);
      whole = deltaSample(mirrored,
          c.sign,
          float3{reflectance, reflectance, reflectance},
          probability,
          1.f);
      return false;
    }
    wi = fromCoat(c,
        reflectDirection(
            woC, sampleGgxVisibleNormal(woC, m_coatAlpha, m_coatAlpha, u)));
    return true;
  }
  case kSheen:
    wi = sampleUniformHemisphere(u);
    return true;
  case kSpecular: {
    if (m_specularDelta) {
      // The mirror direction has mu_i = mu_o: the sheen scaling evaluates
      // at wo, and so do both coat passes unless the coat is tilted.
      const float scale = (1.f - c.coatO)
                          * (1.f - coatAlbedo(toCoat(c, mirror(wo)).z))
                          * (1.f - c.sheenO);
      whole = deltaSample(mirror(wo),
          c.sign,
          specularFresnel(c.cosO) * scale,
          probability,
          1.f);
      return false;
    }
    wi = reflectDirection(wo, m_lobe.sampleVisibleNormal(wo, u));
    return true;
  }
  case kSpecularMulti:
  case kDiffuse:
    wi = sampleCosineHemisphere(u);
    return true;
  case kTransmission:
    return sampleTransmission(c, u, wi, whole);
  case kTransmissionMulti: {
    const float3 wr = sampleCosineHemisphere(u);
    wi = {wr.x, wr.y, -wr.z};
    return true;
  }
  default:
    return false;
  }
}

// The transmission lobe's part of sampleDirection().
bool Bsdf::sampleTransmission(
    const Context &c, float2 u, float3 &wi, BsdfSample &whole) const
{
  const float3 wo = c.wo;
  const float probability = c.probability[kTransmission];
  const float scale = (1.f - c.coatO) * (1.f - c.sheenO) * m_transmissionWeight;
  if (!m_volume) {
    if (m_specularDelta) {
      whole = deltaSample(-wo,
          c.sign,
          m_baseColor * (scale * (1.f - c.dielectricO)),
          probability,
          1.f);
      return false;
    }
    const float3 wr = reflectDirection(wo, m_lobe.sampleVisibleNormal(wo, u));
    wi = {wr.x, wr.y, -wr.z};
    return true;
  }
  if (m_specularDelta) {
    float3 refracted;
    if (!refractDirection(wo, {0.f, 0.f, 1.f}, 1.f / m_ior, refracted))
      return false;
    const float fresnel = maxComponent(dielectricFresnel(c.cosO));
    // Entering the medium, radiance scales by 1 / ior^2.
    whole = deltaSample(refracted,
        c.sign,
        m_baseColor * (scale * (1.f - fresnel) / (m_ior * m_ior)),
        probability,
        m_ior);
    return false;
  }
  const float3 h = m_lobe.sampleVisibleNormal(wo, u);
  return refractDirection(wo, h, 1.f / m_ior, wi);
}

// The sample of a non-delta lobe's direction wi (our frame): the mixture
// density and the summed f over every non-delta lobe, the one-sample MIS
// estimator, consistent with eval() and pdf() by construction.
BsdfSample Bsdf::sampleFromDirection(
    const Context &c, int lobe, float3 wi) const
{
  const bool transmission = lobe == kTransmission || lobe == kTransmissionMulti;
  if (transmission ? wi.z >= 0.f : wi.z <= 0.f)
    return {};
  const float3 wiCaller{wi.x, wi.y, wi.z * c.sign};
  BsdfSample s;
  float3 f;
  float pdf;
  evaluate(c, wiCaller, f, pdf);
  if (!(pdf > 0.f) || maxComponent(f) <= 0.f)
    return s;
  s.wi = wiCaller;
  s.f = f;
  s.pdf = pdf;
  s.weight = f * (std::abs(wi.z) / pdf);
  s.relativeIor = transmission && m_volume ? m_ior : 1.f;
  s.flags = transmission ? kBsdfTransmission : kBsdfReflection;
  return s;
}

} // namespace prism
