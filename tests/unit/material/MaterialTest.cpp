// Materials: parameters from constants, samplers and attributes, the spec's
// opacity rules, alpha modes and coverage, and invalid input.
#include "Device.h"
#include "array/Array.h"
#include "material/Matte.h"
#include "material/PhysicallyBased.h"
#include "object/UnknownObject.h"
#include "sampler/Image2D.h"
#include "sampler/Transform.h"

#include "anari/frontend/type_utility.h"

#include <gtest/gtest.h>

#include <cmath>

#include <limits>
#include <string>
#include <vector>

namespace prism {
namespace {

class MaterialTest : public ::testing::Test
{
 protected:
  void SetUp() override
  {
    ANARIStatusCallback callback = [](const void *user,
                                       ANARIDevice,
                                       ANARIObject,
                                       ANARIDataType,
                                       ANARIStatusSeverity,
                                       ANARIStatusCode,
                                       const char *message) {
      ((std::vector<std::string> *)user)->push_back(message);
    };
    const auto device = (ANARIObject)m_device.this_device();
    m_device.setParameter(
        device, "statusCallback", ANARI_STATUS_CALLBACK, &callback);
    m_device.setParameter(
        device, "statusCallbackUserData", ANARI_VOID_POINTER, &m_messages);
  }
  void TearDown() override
  {
    for (Object *object : m_objects)
      object->releaseInternal();
  }

  template <typename T>
  T *make()
  {
    auto *object = new T(m_device);
    m_objects.push_back(object);
    return object;
  }
  // For object types `mem` is the Object itself.
  static void set(
      Object *object, const char *name, ANARIDataType type, const void *mem)
  {
    Object *value = anari::isObject(type) ? (Object *)mem : nullptr;
    object->stageParameter(name, Parameter::make(type, mem, value));
  }
  static void set(Object *object, const char *name, const char *value)
  {
    set(object, name, ANARI_STRING, value);
  }
  static void set(Object *object, const char *name, float value)
  {
    set(object, name, ANARI_FLOAT32, &value);
  }
  static void set(Object *object, const char *name, float3 value)
  {
    set(object, name, ANARI_FLOAT32_VEC3, &value);
  }
  static void set(Object *object, const char *name, Sampler *sampler)
  {
    set(object, name, ANARI_SAMPLER, sampler);
  }
  static void commit(Object *object)
  {
    object->snapshotForCommit();
    object->applyCommit();
    object->finalize();
  }
  // A transform sampler: outTransform * `input` + outOffset.
  Transform *transform(
      const char *input, const mat4 &outTransform, float4 outOffset)
  {
    auto *sampler = make<Transform>();
    set(sampler, "inAttribute", input);
    set(sampler, "outTransform", ANARI_FLOAT32_MAT4, &outTransform);
    set(sampler, "outOffset", ANARI_FLOAT32_VEC4, &outOffset);
    commit(sampler);
    return sampler;
  }
  bool reported(std::initializer_list<const char *> parts) const
  {
    for (const std::string &message : m_messages) {
      bool all = true;
      for (const char *part : parts)
        all = all && message.find(part) != std::string::npos;
      if (all)
        return true;
    }
    return false;
  }

  std::vector<std::string> m_messages;
  Device m_device{nullptr};
  std::vector<Object *> m_objects;
};

// (x, y, z, w) -> (y, x, z, w): a swizzle as glTF's metallicRoughness needs.
constexpr mat4 kSwapXY{
    {{0.f, 1.f, 0.f, 0.f}, {1.f, 0.f, 0.f, 0.f}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
constexpr float4 kZero{0.f, 0.f, 0.f, 0.f};

AttributeValues with(Attribute attribute, float4 value)
{
  AttributeValues attributes;
  attributes[attribute] = value;
  return attributes;
}

// ---------------------------------------------------------------------------
// matte

TEST_F(MaterialTest, MatteDefaults)
{
  auto *matte = make<Matte>();
  commit(matte);
  EXPECT_TRUE(matte->isValid());
  EXPECT_EQ(matte->baseColorAndOpacity({}), (float4{0.8f, 0.8f, 0.8f, 1.f}));
  EXPECT_EQ(matte->alphaMode(), AlphaMode::Opaque);
  EXPECT_EQ(matte->alphaCutoff(), 0.5f);
  EXPECT_EQ(matte->coverage(0.f), 1.f);
  EXPECT_TRUE(m_messages.empty()) << m_messages.front();
}

TEST_F(MaterialTest, MatteConstants)
{
  auto *matte = make<Matte>();
  set(matte, "color", float3{0.2f, 0.4f, 0.6f});
  set(matte, "opacity", 0.5f);
  set(matte, "alphaMode", "blend");
  commit(matte);
  const float4 base = matte->baseColorAndOpacity({});
  EXPECT_EQ(base, (float4{0.2f, 0.4f, 0.6f, 0.5f}));
  EXPECT_EQ(matte->coverage(base.w), 0.5f);
  // Constants do not depend on the attributes, the color attribute included.
  const AttributeValues red = with(Attribute::Color, {1.f, 0.f, 0.f, 0.25f});
  EXPECT_EQ(matte->baseColorAndOpacity(red), base);
  EXPECT_TRUE(m_messages.empty()) << m_messages.front();
}

TEST_F(MaterialTest, MatteColorAttributeAlphaScalesOpacity)
{
  auto *matte = make<Matte>();
  set(matte, "color", "color");
  set(matte, "opacity", 0.8f);
  commit(matte);
  EXPECT_EQ(matte->color().source(), MaterialInput<float3>::Source::Attribute);
  const AttributeValues hit = with(Attribute::Color, {0.1f, 0.2f, 0.3f, 0.5f});
  EXPECT_EQ(matte->baseColorAndOpacity(hit), (float4{0.1f, 0.2f, 0.3f, 0.4f}));
  // An unset color attribute is (0, 0, 0, 1) like any other (spec 3.13).
  EXPECT_EQ(matte->baseColorAndOpacity({}), (float4{0.f, 0.f, 0.f, 0.8f}));
}

TEST_F(MaterialTest, MatteColorAndOpacityFromSamplers)
{
  // color = attribute2 with its channels swapped, plus 0.1 in blue.
  Transform *color = transform("attribute2", kSwapXY, {0.f, 0.f, 0.1f, 0.f});
  // opacity = attribute3.x / 2 (only the first component is used).
  mat4 half{};
  half.col[0] = {0.5f, 0.f, 0.f, 0.f};
  Transform *opacity = transform("attribute3", half, kZero);
  auto *matte = make<Matte>();
  set(matte, "color", color);
  set(matte, "opacity", opacity);
  commit(matte);
  AttributeValues hit;
  hit[Attribute::Attribute2] = {0.25f, 0.5f, 0.5f, 0.5f};
  hit[Attribute::Attribute3] = {0.5f, 9.f, 9.f, 9.f};
  // opacity 0.25 times the sampled color's fourth component 0.5
  EXPECT_EQ(
      matte->baseColorAndOpacity(hit), (float4{0.5f, 0.25f, 0.6f, 0.125f}));
  EXPECT_EQ(matte->color().sampler(), color);
}

TEST_F(MaterialTest, MatteOpacityFromAttributeUsesTheFirstComponent)
{
  auto *matte = make<Matte>();
  set(matte, "opacity", "attribute0");
  set(matte, "alphaMode", "blend");
  commit(matte);
  const AttributeValues hit =
      with(Attribute::Attribute0, {0.75f, 0.f, 0.f, 1.f});
  EXPECT_EQ(matte->baseColorAndOpacity(hit).w, 0.75f);
  EXPECT_EQ(matte->coverage(0.75f), 0.75f);
}

TEST_F(MaterialTest, AlphaModesDecideCoverage)
{
  auto *matte = make<Matte>();
  set(matte, "alphaMode", "mask");
  set(matte, "alphaCutoff", 0.3f);
  commit(matte);
  EXPECT_EQ(matte->alphaMode(), AlphaMode::Mask);
  EXPECT_EQ(matte->alphaCutoff(), 0.3f);
  EXPECT_EQ(matte->coverage(0.29f), 0.f);
  EXPECT_EQ(matte->coverage(0.3f), 1.f);
  EXPECT_EQ(matte->coverage(0.9f), 1.f);

  set(matte, "alphaMode", "blend");
  commit(matte);
  EXPECT_EQ(matte->coverage(0.29f), 0.29f);

  set(matte, "alphaMode", "opaque");
  commit(matte);
  EXPECT_EQ(matte->coverage(0.f), 1.f);

  set(matte, "alphaMode", "dither");
  commit(matte);
  EXPECT_EQ(matte->alphaMode(), AlphaMode::Opaque);
  EXPECT_TRUE(reported({"matte", "'alphaMode'", "dither"}));
}

TEST_F(MaterialTest, WrongTypesWarnAndUseDefaults)
{
  auto *matte = make<Matte>();
  const float4 rgba{0.f, 1.f, 0.f, 1.f};
  set(matte, "color", ANARI_FLOAT32_VEC4, &rgba);
  set(matte, "opacity", "texcoord");
  commit(matte);
  EXPECT_EQ(matte->baseColorAndOpacity({}), (float4{0.8f, 0.8f, 0.8f, 1.f}));
  EXPECT_TRUE(reported({"'color'", "ANARI_FLOAT32_VEC4", "ANARI_SAMPLER"}));
  EXPECT_TRUE(reported({"'opacity'", "texcoord", "not a surface attribute"}));
}

TEST_F(MaterialTest, UnusableEmissionIsReportedAndEmitsNothing)
{
  auto *pbr = make<PhysicallyBased>();
  set(pbr, "emissive", float3{-1.f, std::nanf(""), 2.f});
  commit(pbr);
  EXPECT_EQ(pbr->evaluate({}).emissive, (float3{0.f, 0.f, 2.f}));
  EXPECT_TRUE(reported({"'emissive'", "non-finite"}));
}

TEST_F(MaterialTest, InvalidSamplerGivesTheDefault)
{
  auto *image = make<Image2D>(); // no 'image': invalid
  commit(image);
  ASSERT_FALSE(image->isValid());
  auto *matte = make<Matte>();
  set(matte, "color", image);
  commit(matte);
  EXPECT_EQ(matte->baseColorAndOpacity({}), (float4{0.8f, 0.8f, 0.8f, 1.f}));
}

TEST_F(MaterialTest, SamplerOfUnknownSubtypeIsReported)
{
  auto *unknown = new UnknownObject(m_device, ANARI_SAMPLER, "noise");
  m_objects.push_back(unknown);
  auto *matte = make<Matte>();
  set(matte, "color", ANARI_SAMPLER, unknown);
  commit(matte);
  EXPECT_EQ(matte->color().source(), MaterialInput<float3>::Source::Constant);
  EXPECT_TRUE(reported({"'color'", "unknown subtype"}));
  EXPECT_EQ(matte->baseColorAndOpacity({}), (float4{0.8f, 0.8f, 0.8f, 1.f}));
}

TEST_F(MaterialTest, SamplerOutlivesItsParameterUntilTheNextCommit)
{
  // An application that unsets the sampler, commits and releases it while a
  // frame renders: the frame still reads the sampler it started with.
  auto *sampler = new Transform(m_device);
  commit(sampler);
  auto *matte = make<Matte>();
  set(matte, "color", sampler);
  commit(matte);
  matte->unstageParameter("color");
  matte->snapshotForCommit(); // anariCommitParameters, not yet flushed
  sampler->releaseInternal(); // anariRelease
  const AttributeValues hit =
      with(Attribute::Attribute0, {0.1f, 0.2f, 0.3f, 1.f});
  EXPECT_EQ(matte->baseColorAndOpacity(hit), (float4{0.1f, 0.2f, 0.3f, 1.f}));
  matte->applyCommit(); // the flush lets go of it
  EXPECT_EQ(matte->baseColorAndOpacity(hit), (float4{0.8f, 0.8f, 0.8f, 1.f}));
}

TEST_F(MaterialTest, DropReferencesRestoresDefaults)
{
  Transform *sampler = transform("attribute0", kIdentityMat4, kZero);
  auto *matte = make<Matte>();
  set(matte, "color", sampler);
  commit(matte);
  matte->dropReferences();
  EXPECT_EQ(matte->color().sampler(), nullptr);
  EXPECT_EQ(matte->baseColorAndOpacity({}), (float4{0.8f, 0.8f, 0.8f, 1.f}));
}

// ---------------------------------------------------------------------------
// physicallyBased

TEST_F(MaterialTest, PhysicallyBasedDefaultsMatchTheJson)
{
  auto *pbr = make<PhysicallyBased>();
  commit(pbr);
  const PhysicallyBased::Values v = pbr->evaluate({});
  EXPECT_EQ(v.baseColor, (float3{1.f, 1.f, 1.f}));
  EXPECT_EQ(v.opacity, 1.f);
  EXPECT_EQ(v.metallic, 1.f);
  EXPECT_EQ(v.roughness, 1.f);
  EXPECT_EQ(v.normal, (float3{0.f, 0.f, 1.f}));
  EXPECT_EQ(v.emissive, (float3{0.f, 0.f, 0.f}));
  EXPECT_EQ(v.occlusion, 1.f);
  EXPECT_EQ(pbr->alphaMode(), AlphaMode::Opaque);
  EXPECT_EQ(pbr->alphaCutoff(), 0.5f);
  EXPECT_EQ(v.specular, 0.f);
  EXPECT_EQ(v.specularColor, (float3{1.f, 1.f, 1.f}));
  EXPECT_EQ(v.clearcoat, 0.f);
  EXPECT_EQ(v.clearcoatRoughness, 0.f);
  EXPECT_EQ(v.clearcoatNormal, (float3{0.f, 0.f, 1.f}));
  EXPECT_EQ(v.transmission, 0.f);
  EXPECT_EQ(v.ior, 1.5f);
  EXPECT_EQ(v.thickness, 0.f);
  EXPECT_EQ(v.attenuationDistance, std::numeric_limits<float>::infinity());
  EXPECT_EQ(v.attenuationColor, (float3{1.f, 1.f, 1.f}));
  EXPECT_EQ(v.sheenColor, (float3{0.f, 0.f, 0.f}));
  EXPECT_EQ(v.sheenRoughness, 0.f);
  EXPECT_EQ(v.iridescence, 0.f);
  EXPECT_EQ(v.iridescenceIor, 1.3f);
  EXPECT_EQ(v.iridescenceThickness, 0.f);
  EXPECT_EQ(pbr->baseColorAndOpacity({}), (float4{1.f, 1.f, 1.f, 1.f}));
  EXPECT_EQ(pbr->inputs().normal.sampler(), nullptr);
  EXPECT_TRUE(m_messages.empty()) << m_messages.front();
}

TEST_F(MaterialTest, PhysicallyBasedReadsEveryParameter)
{
  auto *pbr = make<PhysicallyBased>();
  auto *normalMap = transform("attribute1", kIdentityMat4, kZero);
  auto *clearcoatNormalMap = transform("attribute2", kIdentityMat4, kZero);
  auto *occlusionMap = transform("attribute3", kIdentityMat4, kZero);
  set(pbr, "baseColor", float3{0.1f, 0.2f, 0.3f});
  set(pbr, "opacity", 0.9f);
  set(pbr, "metallic", 0.25f);
  set(pbr, "roughness", 0.35f);
  set(pbr, "normal", normalMap);
  set(pbr, "emissive", float3{4.f, 5.f, 6.f});
  set(pbr, "occlusion", occlusionMap);
  set(pbr, "alphaMode", "mask");
  set(pbr, "alphaCutoff", 0.7f);
  set(pbr, "specular", 0.45f);
  set(pbr, "specularColor", float3{0.5f, 0.6f, 0.7f});
  set(pbr, "clearcoat", 0.55f);
  set(pbr, "clearcoatRoughness", 0.65f);
  set(pbr, "clearcoatNormal", clearcoatNormalMap);
  set(pbr, "transmission", 0.75f);
  set(pbr, "ior", 1.33f);
  set(pbr, "thickness", 2.f);
  set(pbr, "attenuationDistance", 3.f);
  set(pbr, "attenuationColor", float3{0.8f, 0.7f, 0.6f});
  set(pbr, "sheenColor", float3{0.3f, 0.2f, 0.1f});
  set(pbr, "sheenRoughness", 0.85f);
  set(pbr, "iridescence", 0.95f);
  set(pbr, "iridescenceIor", 1.8f);
  set(pbr, "iridescenceThickness", 400.f);
  commit(pbr);
  // Every name was read: nothing was reported as unknown.
  EXPECT_TRUE(m_messages.empty()) << m_messages.front();

  AttributeValues hit;
  hit[Attribute::Attribute1] = {0.f, 0.6f, 0.8f, 1.f};
  hit[Attribute::Attribute2] = {0.6f, 0.f, 0.8f, 1.f};
  hit[Attribute::Attribute3] = {0.4f, 0.f, 0.f, 1.f};
  const PhysicallyBased::Values v = pbr->evaluate(hit);
  EXPECT_EQ(v.baseColor, (float3{0.1f, 0.2f, 0.3f}));
  EXPECT_EQ(v.opacity, 0.9f);
  EXPECT_EQ(v.metallic, 0.25f);
  EXPECT_EQ(v.roughness, 0.35f);
  EXPECT_EQ(v.normal, (float3{0.f, 0.6f, 0.8f}));
  EXPECT_EQ(v.emissive, (float3{4.f, 5.f, 6.f}));
  EXPECT_EQ(v.occlusion, 0.4f);
  EXPECT_EQ(pbr->alphaMode(), AlphaMode::Mask);
  EXPECT_EQ(pbr->alphaCutoff(), 0.7f);
  EXPECT_EQ(pbr->coverage(v.opacity), 1.f);
  EXPECT_EQ(v.specular, 0.45f);
  EXPECT_EQ(v.specularColor, (float3{0.5f, 0.6f, 0.7f}));
  EXPECT_EQ(v.clearcoat, 0.55f);
  EXPECT_EQ(v.clearcoatRoughness, 0.65f);
  EXPECT_EQ(v.clearcoatNormal, (float3{0.6f, 0.f, 0.8f}));
  EXPECT_EQ(v.transmission, 0.75f);
  EXPECT_EQ(v.ior, 1.33f);
  EXPECT_EQ(v.thickness, 2.f);
  EXPECT_EQ(v.attenuationDistance, 3.f);
  EXPECT_EQ(v.attenuationColor, (float3{0.8f, 0.7f, 0.6f}));
  EXPECT_EQ(v.sheenColor, (float3{0.3f, 0.2f, 0.1f}));
  EXPECT_EQ(v.sheenRoughness, 0.85f);
  EXPECT_EQ(v.iridescence, 0.95f);
  EXPECT_EQ(v.iridescenceIor, 1.8f);
  EXPECT_EQ(v.iridescenceThickness, 400.f);
  EXPECT_EQ(pbr->inputs().normal.sampler(), normalMap);
}

TEST_F(MaterialTest, PhysicallyBasedInputsFromSamplersAndAttributes)
{
  // glTF metallicRoughness: one texture, roughness in y via a swizzle.
  Transform *roughness = transform("attribute0", kSwapXY, kZero);
  auto *pbr = make<PhysicallyBased>();
  set(pbr, "metallic", "attribute0");
  set(pbr, "roughness", roughness);
  set(pbr, "emissive", "worldNormal");
  set(pbr, "ior", "attribute1"); // the JSON lets ior vary too
  commit(pbr);
  AttributeValues hit;
  hit[Attribute::Attribute0] = {0.2f, 0.7f, 0.f, 1.f};
  hit[Attribute::Attribute1] = {1.4f, 0.f, 0.f, 1.f};
  hit[Attribute::WorldNormal] = {0.f, 1.f, 0.f, 1.f};
  const PhysicallyBased::Values v = pbr->evaluate(hit);
  EXPECT_EQ(v.metallic, 0.2f);
  EXPECT_EQ(v.roughness, 0.7f);
  EXPECT_EQ(v.emissive, (float3{0.f, 1.f, 0.f}));
  EXPECT_EQ(v.ior, 1.4f);
}

TEST_F(MaterialTest, PhysicallyBasedBaseColorAlphaOnlyOutsideOpaque)
{
  Transform *baseColor = transform("attribute0", kIdentityMat4, kZero);
  auto *pbr = make<PhysicallyBased>();
  set(pbr, "baseColor", baseColor);
  set(pbr, "opacity", 0.5f);
  commit(pbr);
  const AttributeValues hit =
      with(Attribute::Attribute0, {0.2f, 0.4f, 0.6f, 0.5f});
  // opaque: the fourth component is not applied
  EXPECT_EQ(pbr->baseColorAndOpacity(hit), (float4{0.2f, 0.4f, 0.6f, 0.5f}));
  set(pbr, "alphaMode", "blend");
  commit(pbr);
  EXPECT_EQ(pbr->baseColorAndOpacity(hit), (float4{0.2f, 0.4f, 0.6f, 0.25f}));
  EXPECT_EQ(pbr->evaluate(hit).opacity, 0.25f);
  EXPECT_EQ(pbr->coverage(0.25f), 0.25f);
  set(pbr, "alphaMode", "mask");
  set(pbr, "alphaCutoff", 0.3f);
  commit(pbr);
  EXPECT_EQ(pbr->coverage(pbr->baseColorAndOpacity(hit).w), 0.f);
}

TEST_F(MaterialTest, PhysicallyBasedMapsAcceptOnlySamplers)
{
  auto *pbr = make<PhysicallyBased>();
  set(pbr, "normal", float3{1.f, 0.f, 0.f});
  set(pbr, "occlusion", "attribute0");
  set(pbr, "clearcoatNormal", 0.5f);
  set(pbr, "attenuationDistance", "attribute0"); // FLOAT32 only
  commit(pbr);
  const PhysicallyBased::Values v = pbr->evaluate({});
  EXPECT_EQ(v.normal, (float3{0.f, 0.f, 1.f}));
  EXPECT_EQ(v.occlusion, 1.f);
  EXPECT_EQ(v.clearcoatNormal, (float3{0.f, 0.f, 1.f}));
  EXPECT_EQ(v.attenuationDistance, std::numeric_limits<float>::infinity());
  EXPECT_TRUE(reported({"'normal'", "ANARI_FLOAT32_VEC3", "ANARI_SAMPLER"}));
  EXPECT_TRUE(reported({"'occlusion'", "ANARI_STRING"}));
  EXPECT_TRUE(reported({"'clearcoatNormal'", "ANARI_FLOAT32"}));
  EXPECT_TRUE(reported({"'attenuationDistance'", "ANARI_STRING"}));
}

// ---------------------------------------------------------------------------
// prism's glTF extensions

TEST_F(MaterialTest, BaseColorFactorMultipliesTheBaseColor)
{
  // PRISM_MATERIAL_BASE_COLOR_FACTOR: a sampled base color times the vertex
  // colors, as glTF multiplies a base color texture by COLOR_0.
  Transform *texture = transform("attribute0", kIdentityMat4, kZero);
  auto *pbr = make<PhysicallyBased>();
  set(pbr, "baseColor", texture);
  set(pbr, "baseColorFactor", "color");
  set(pbr, "alphaMode", "blend");
  commit(pbr);
  EXPECT_TRUE(pbr->colorReadsAttributes());
  AttributeValues hit;
  hit[Attribute::Attribute0] = {0.5f, 1.f, 0.25f, 0.5f};
  hit[Attribute::Color] = {0.5f, 0.25f, 1.f, 0.5f};
  EXPECT_EQ(
      pbr->baseColorAndOpacity(hit), (float4{0.25f, 0.25f, 0.25f, 0.25f}));
  EXPECT_EQ(pbr->evaluate(hit).baseColor, (float3{0.25f, 0.25f, 0.25f}));
  // Opaque: the alphas multiply, but only blend and mask use them.
  set(pbr, "alphaMode", "opaque");
  commit(pbr);
  EXPECT_EQ(pbr->baseColorAndOpacity(hit).w, 1.f);
  // A constant factor (alpha 1) scales a constant base color.
  auto *constant = make<PhysicallyBased>();
  set(constant, "baseColor", float3{0.5f, 0.5f, 1.f});
  set(constant, "baseColorFactor", float3{0.5f, 1.f, 0.25f});
  commit(constant);
  EXPECT_FALSE(constant->colorReadsAttributes());
  EXPECT_EQ(
      constant->baseColorAndOpacity({}), (float4{0.25f, 0.5f, 0.25f, 1.f}));
  EXPECT_TRUE(m_messages.empty()) << m_messages.front();
}

TEST_F(MaterialTest, UnlitEmitsItsBaseColorOverABlackBsdf)
{
  // PRISM_MATERIAL_UNLIT: the base color (times the factor) is emitted,
  // the BSDF reflects nothing, the albedo is the base color, and the
  // surface is not a light to sample.
  auto *pbr = make<PhysicallyBased>();
  set(pbr, "baseColor", "color");
  set(pbr, "baseColorFactor", float3{1.f, 0.5f, 0.5f});
  set(pbr, "emissive", float3{5.f, 5.f, 5.f}); // ignored when unlit
  set(pbr, "opacity", 0.5f);
  set(pbr, "alphaMode", "blend");
  const bool on = true;
  set(pbr, "unlit", ANARI_BOOL, &on);
  commit(pbr);
  const AttributeValues hit = with(Attribute::Color, {0.2f, 0.4f, 0.8f, 1.f});
  const MaterialShading shading = pbr->shade(hit);
  EXPECT_EQ(shading.emissive, (float3{0.2f, 0.2f, 0.4f}));
  EXPECT_EQ(shading.albedo, (float3{0.2f, 0.2f, 0.4f}));
  EXPECT_EQ(shading.opacity, 0.5f);
  EXPECT_FALSE(shading.hasNormalMap);
  const Bsdf bsdf(shading.bsdf);
  const float3 wo = normalize(float3{0.3f, 0.1f, 1.f});
  for (const float3 wi : {float3{0.f, 0.f, 1.f},
           normalize(float3{-0.3f, -0.1f, 1.f}),
           normalize(float3{0.5f, 0.5f, 0.2f})})
    EXPECT_EQ(bsdf.eval(wo, wi), (float3{0.f, 0.f, 0.f}));
  const BsdfSample sample = bsdf.sample(wo, {0.3f, 0.6f}, 0.5f);
  EXPECT_TRUE(!sample.valid() || maxComponent(sample.weight) == 0.f);
  float3 radiance;
  EXPECT_FALSE(pbr->constantEmission(radiance));
  // Not unlit: the same inputs shade as usual.
  const bool off = false;
  set(pbr, "unlit", ANARI_BOOL, &off);
  commit(pbr);
  EXPECT_EQ(pbr->shade(hit).emissive, (float3{5.f, 5.f, 5.f}));
  EXPECT_TRUE(m_messages.empty()) << m_messages.front();
}

TEST_F(MaterialTest, DoubleSidedByDefault)
{
  auto *matte = make<Matte>();
  auto *pbr = make<PhysicallyBased>();
  commit(matte);
  commit(pbr);
  EXPECT_TRUE(matte->doubleSided());
  EXPECT_TRUE(pbr->doubleSided());
  const bool off = false;
  set(matte, "doubleSided", ANARI_BOOL, &off);
  set(pbr, "doubleSided", ANARI_BOOL, &off);
  commit(matte);
  commit(pbr);
  EXPECT_FALSE(matte->doubleSided());
  EXPECT_FALSE(pbr->doubleSided());
  EXPECT_TRUE(m_messages.empty()) << m_messages.front();
}

// The BSDF of `shading` and `bsdf` agree on a few direction pairs.
void expectSameBsdf(const Bsdf &bsdf, const MaterialShading &shading)
{
  const Bsdf built(shading.bsdf);
  const float3 wo = normalize(float3{0.3f, -0.2f, 0.9f});
  for (const float3 wi : {float3{0.f, 0.f, 1.f},
           normalize(float3{-0.5f, 0.4f, 0.6f}),
           normalize(float3{0.3f, -0.2f, -0.9f})}) {
    EXPECT_EQ(bsdf.eval(wo, wi), built.eval(wo, wi));
    EXPECT_EQ(bsdf.pdf(wo, wi), built.pdf(wo, wi));
  }
}

TEST_F(MaterialTest, ConstantShadingFollowsEveryCommit)
{
  auto *matte = make<Matte>();
  set(matte, "color", float3{0.2f, 0.4f, 0.6f});
  commit(matte);
  const ConstantShading *constant = matte->constantShading();
  ASSERT_NE(constant, nullptr);
  EXPECT_EQ(constant->shading.bsdf.baseColor, (float3{0.2f, 0.4f, 0.6f}));
  EXPECT_EQ(constant->shading.albedo, (float3{0.2f, 0.4f, 0.6f}));
  expectSameBsdf(constant->bsdf, matte->shade({}));
  // A new color is the constant's after the next commit.
  set(matte, "color", float3{0.9f, 0.1f, 0.1f});
  commit(matte);
  ASSERT_NE(matte->constantShading(), nullptr);
  EXPECT_EQ(matte->constantShading()->shading.bsdf.baseColor,
      (float3{0.9f, 0.1f, 0.1f}));
  expectSameBsdf(matte->constantShading()->bsdf, matte->shade({}));
  // A color read from attributes differs from hit to hit: no constant.
  set(matte, "color", "color");
  commit(matte);
  EXPECT_EQ(matte->constantShading(), nullptr);
  set(matte, "color", float3{0.5f, 0.5f, 0.5f});
  commit(matte);
  ASSERT_NE(matte->constantShading(), nullptr);
  EXPECT_EQ(matte->constantShading()->shading.bsdf.baseColor,
      (float3{0.5f, 0.5f, 0.5f}));
}

TEST_F(MaterialTest, PhysicallyBasedConstantShadingMatchesShade)
{
  auto *pbr = make<PhysicallyBased>();
  set(pbr, "baseColor", float3{0.9f, 0.6f, 0.3f});
  set(pbr, "metallic", 0.4f);
  set(pbr, "roughness", 0.3f);
  set(pbr, "clearcoat", 0.5f);
  set(pbr, "emissive", float3{0.f, 2.f, 0.f});
  set(pbr, "transmission", 0.2f);
  set(pbr, "thickness", 1.f);
  set(pbr, "attenuationColor", float3{0.5f, 0.5f, 1.f});
  set(pbr, "attenuationDistance", 2.f);
  commit(pbr);
  const ConstantShading *constant = pbr->constantShading();
  ASSERT_NE(constant, nullptr);
  const MaterialShading shaded = pbr->shade({});
  EXPECT_EQ(constant->shading.emissive, shaded.emissive);
  EXPECT_EQ(constant->shading.attenuation, shaded.attenuation);
  EXPECT_EQ(constant->shading.opacity, shaded.opacity);
  EXPECT_EQ(constant->shading.bsdf.metallic, 0.4f);
  EXPECT_EQ(
      constant->bsdf.isVolumeBoundary(), Bsdf(shaded.bsdf).isVolumeBoundary());
  expectSameBsdf(constant->bsdf, shaded);
  // A normal map bends the frame hit by hit: no constant.
  Transform *normal = transform("attribute0", kIdentityMat4, kZero);
  set(pbr, "normal", normal);
  commit(pbr);
  EXPECT_EQ(pbr->constantShading(), nullptr);
}

TEST_F(MaterialTest, WorksThroughTheDeviceApi)
{
  ANARISampler sampler = m_device.newSampler("transform");
  ANARIMaterial handle = m_device.newMaterial("matte");
  m_device.setParameter(handle, "color", ANARI_SAMPLER, &sampler);
  const char *mode = "blend";
  m_device.setParameter(handle, "alphaMode", ANARI_STRING, mode);
  m_device.commitParameters(handle);
  m_device.commitParameters(sampler);
  m_device.release(sampler); // the material keeps it
  m_device.flushCommits();
  auto *matte = dynamic_cast<Matte *>(m_device.lookup(handle));
  ASSERT_NE(matte, nullptr);
  const AttributeValues hit =
      with(Attribute::Attribute0, {0.1f, 0.2f, 0.3f, 0.5f});
  EXPECT_EQ(matte->baseColorAndOpacity(hit), (float4{0.1f, 0.2f, 0.3f, 0.5f}));
  EXPECT_EQ(matte->alphaMode(), AlphaMode::Blend);
  m_device.release(handle);
  EXPECT_TRUE(m_messages.empty()) << m_messages.front();
}

TEST_F(MaterialTest, FactoryKnowsEverySubtype)
{
  for (const char *subtype : {"matte", "physicallyBased"}) {
    Material *material = createMaterial(m_device, subtype);
    ASSERT_NE(material, nullptr) << subtype;
    EXPECT_EQ(material->subtype(), subtype);
    EXPECT_EQ(material->type(), ANARI_MATERIAL);
    material->releaseInternal();
  }
  EXPECT_EQ(createMaterial(m_device, "principled"), nullptr);
}

} // namespace
} // namespace prism
