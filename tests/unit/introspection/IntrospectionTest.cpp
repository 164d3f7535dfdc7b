// Introspection answers checked against values of the Khronos API JSON.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "anari/frontend/type_utility.h"
#include "introspection/Introspection.h"

namespace prism::introspection {
namespace {

// What the process-wide catalog implements: a realistic subset, leaving out
// KHR_GEOMETRY_CURVE, KHR_CAMERA_ORTHOGRAPHIC, KHR_CAMERA_STEREO,
// KHR_RENDERER_BACKGROUND_IMAGE, KHR_SAMPLER_IMAGExD_CLAMP_TO_BORDER and all
// compressed-sampler extensions so their absence can be checked.
const char *kImplemented[] = {"ANARI_KHR_GEOMETRY_TRIANGLE",
    "ANARI_KHR_GEOMETRY_SPHERE",
    "ANARI_KHR_GEOMETRY_QUAD",
    "ANARI_KHR_CAMERA_PERSPECTIVE",
    "ANARI_KHR_CAMERA_DEPTH_OF_FIELD",
    "ANARI_KHR_FRAME_CHANNEL_ALBEDO",
    "ANARI_KHR_FRAME_CHANNEL_PRIMITIVE_ID",
    "ANARI_KHR_FRAME_CHANNEL_OBJECT_ID",
    "ANARI_KHR_INSTANCE_TRANSFORM",
    "ANARI_KHR_LIGHT_DIRECTIONAL",
    "ANARI_KHR_MATERIAL_MATTE",
    "ANARI_KHR_MATERIAL_PHYSICALLY_BASED",
    "ANARI_KHR_RENDERER_BACKGROUND_COLOR",
    "ANARI_KHR_SAMPLER_IMAGE2D",
    "ANARI_PRISM_NOT_IN_THE_JSON",
    nullptr};
const char *kRenderers[] = {
    "default", "pathtracer", "raycast", "ao", "debug", nullptr};

// Every extension of the API definitions, as a device implementing all of
// them would list them.
std::vector<const char *> allExtensions()
{
  std::vector<const char *> all(
      tables::kExtensions, tables::kExtensions + tables::kExtensionCount);
  all.push_back(nullptr);
  return all;
}

std::vector<std::string> strings(const void *list)
{
  std::vector<std::string> out;
  for (auto *s = static_cast<const char *const *>(list); s && *s; ++s)
    out.emplace_back(*s);
  return out;
}

std::vector<int> dataTypes(const void *list)
{
  std::vector<int> out;
  for (auto *t = static_cast<const ANARIDataType *>(list);
       t && int(*t) != ANARI_UNKNOWN;
       ++t)
    out.push_back(int(*t));
  return out;
}

bool contains(const std::vector<std::string> &list, const char *s)
{
  for (const std::string &item : list) {
    if (item == s)
      return true;
  }
  return false;
}

// Parameter names/types of an object's "parameter" info.
std::vector<std::pair<std::string, int>> parameterList(const void *info)
{
  std::vector<std::pair<std::string, int>> out;
  for (auto *p = static_cast<const ANARIParameter *>(info); p && p->name; ++p)
    out.emplace_back(p->name, int(p->type));
  return out;
}

bool hasParameter(
    const std::vector<std::pair<std::string, int>> &list, const char *name)
{
  for (const auto &p : list) {
    if (p.first == name)
      return true;
  }
  return false;
}

class Introspection : public testing::Test
{
 protected:
  static void SetUpTestSuite()
  {
    setImplementedExtensions(kImplemented, kRenderers);
  }
};

TEST_F(Introspection, DeviceExtensionsAreTheImplementedList)
{
  auto list = strings(deviceExtensions());
  ASSERT_EQ(list.size(), std::size(kImplemented) - 1);
  for (size_t i = 0; i + 1 < std::size(kImplemented); ++i)
    EXPECT_EQ(list[i], kImplemented[i]);
  EXPECT_EQ(deviceExtensions(), deviceExtensions()) << "stable pointer";
}

TEST_F(Introspection, LaterSetCallsAreIgnored)
{
  const char *other[] = {"ANARI_KHR_GEOMETRY_CURVE", nullptr};
  const char **before = deviceExtensions();
  setImplementedExtensions(other, nullptr);
  EXPECT_EQ(deviceExtensions(), before);
  EXPECT_EQ(objectInfo(ANARI_GEOMETRY, "curve", "description", ANARI_STRING),
      nullptr);
}

TEST_F(Introspection, GeometrySubtypesAreThoseOfImplementedExtensions)
{
  auto subtypes = strings(objectSubtypes(ANARI_GEOMETRY));
  EXPECT_TRUE(contains(subtypes, "triangle"));
  EXPECT_TRUE(contains(subtypes, "sphere"));
  EXPECT_TRUE(contains(subtypes, "quad"));
  EXPECT_FALSE(contains(subtypes, "curve"));
  EXPECT_FALSE(contains(subtypes, "cone"));
  EXPECT_EQ(subtypes.size(), 3u);
  EXPECT_EQ(objectSubtypes(ANARI_GEOMETRY), objectSubtypes(ANARI_GEOMETRY));
}

TEST_F(Introspection, SubtypeOfUnimplementedExtensionIsNotReported)
{
  EXPECT_EQ(
      objectInfo(ANARI_GEOMETRY, "curve", "parameter", ANARI_PARAMETER_LIST),
      nullptr);
  EXPECT_EQ(parameterInfo(ANARI_GEOMETRY,
                "curve",
                "vertex.position",
                ANARI_ARRAY1D,
                "required",
                ANARI_BOOL),
      nullptr);
  EXPECT_EQ(findParameter(ANARI_GEOMETRY, "curve", "vertex.position"), nullptr);
  EXPECT_FALSE(contains(strings(objectSubtypes(ANARI_CAMERA)), "orthographic"));
  EXPECT_EQ(
      objectInfo(ANARI_CAMERA, "orthographic", "description", ANARI_STRING),
      nullptr);
}

TEST_F(Introspection, TypesWithoutSubtypesHaveNoSubtypeList)
{
  EXPECT_EQ(objectSubtypes(ANARI_FRAME), nullptr);
  EXPECT_EQ(objectSubtypes(ANARI_SURFACE), nullptr);
  EXPECT_EQ(objectSubtypes(ANARI_WORLD), nullptr);
  EXPECT_EQ(objectSubtypes(ANARI_FLOAT32), nullptr);
  // No volume extension is implemented.
  EXPECT_EQ(objectSubtypes(ANARI_VOLUME), nullptr);
}

TEST_F(Introspection, TriangleVertexPositionIsARequiredVec3Array)
{
  const void *required = parameterInfo(ANARI_GEOMETRY,
      "triangle",
      "vertex.position",
      ANARI_ARRAY1D,
      "required",
      ANARI_BOOL);
  ASSERT_NE(required, nullptr);
  EXPECT_EQ(*static_cast<const int8_t *>(required), 1);
  EXPECT_EQ(*static_cast<const int32_t *>(required), 1) << "32-bit readers";

  auto elementTypes = dataTypes(parameterInfo(ANARI_GEOMETRY,
      "triangle",
      "vertex.position",
      ANARI_ARRAY1D,
      "elementType",
      ANARI_DATA_TYPE_LIST));
  EXPECT_EQ(elementTypes, std::vector<int>{ANARI_FLOAT32_VEC3});

  auto *description = static_cast<const char *>(parameterInfo(ANARI_GEOMETRY,
      "triangle",
      "vertex.position",
      ANARI_ARRAY1D,
      "description",
      ANARI_STRING));
  ASSERT_NE(description, nullptr);
  EXPECT_STREQ(description, "vertex position");

  auto *notRequired = static_cast<const int8_t *>(parameterInfo(ANARI_GEOMETRY,
      "triangle",
      "vertex.normal",
      ANARI_ARRAY1D,
      "required",
      ANARI_BOOL));
  ASSERT_NE(notRequired, nullptr);
  EXPECT_EQ(*notRequired, 0);
}

TEST_F(Introspection, TriangleParameterListHasEveryParameterOnce)
{
  auto list = parameterList(objectInfo(
      ANARI_GEOMETRY, "triangle", "parameter", ANARI_PARAMETER_LIST));
  EXPECT_EQ(list.size(), 27u); // khr_geometry_triangle.json
  std::pair<std::string, int> position{"vertex.position", ANARI_ARRAY1D};
  EXPECT_NE(std::find(list.begin(), list.end(), position), list.end());
  // KHR_GEOMETRY_TRIANGLE_MOTION_DEFORMATION is not implemented.
  EXPECT_FALSE(hasParameter(list, "motion.vertex.position"));
}

TEST_F(Introspection, SphereRadiusDefaultIsTypedFloat)
{
  auto *radius = static_cast<const float *>(parameterInfo(ANARI_GEOMETRY,
      "sphere",
      "radius",
      ANARI_FLOAT32,
      "default",
      ANARI_FLOAT32));
  ASSERT_NE(radius, nullptr);
  EXPECT_EQ(*radius, 1.f);
  // The default has the parameter's type; any other infoType has none.
  EXPECT_EQ(parameterInfo(ANARI_GEOMETRY,
                "sphere",
                "radius",
                ANARI_FLOAT32,
                "default",
                ANARI_FLOAT64),
      nullptr);
  // vertex.radius has no default.
  EXPECT_EQ(parameterInfo(ANARI_GEOMETRY,
                "sphere",
                "vertex.radius",
                ANARI_ARRAY1D,
                "default",
                ANARI_ARRAY1D),
      nullptr);
}

TEST_F(Introspection, VectorBoolStringAndInfiniteDefaults)
{
  auto *direction = static_cast<const float *>(parameterInfo(ANARI_CAMERA,
      "perspective",
      "direction",
      ANARI_FLOAT32_VEC3,
      "default",
      ANARI_FLOAT32_VEC3));
  ASSERT_NE(direction, nullptr);
  EXPECT_EQ(direction[0], 0.f);
  EXPECT_EQ(direction[1], 0.f);
  EXPECT_EQ(direction[2], -1.f);

  auto *visible = static_cast<const int8_t *>(parameterInfo(
      ANARI_SURFACE, nullptr, "visible", ANARI_BOOL, "default", ANARI_BOOL));
  ASSERT_NE(visible, nullptr);
  EXPECT_EQ(*visible, 1);

  auto *alphaMode = static_cast<const char *>(parameterInfo(ANARI_MATERIAL,
      "matte",
      "alphaMode",
      ANARI_STRING,
      "default",
      ANARI_STRING));
  ASSERT_NE(alphaMode, nullptr);
  EXPECT_STREQ(alphaMode, "opaque");

  auto *color = static_cast<const float *>(parameterInfo(ANARI_MATERIAL,
      "matte",
      "color",
      ANARI_FLOAT32_VEC3,
      "default",
      ANARI_FLOAT32_VEC3));
  ASSERT_NE(color, nullptr);
  EXPECT_FLOAT_EQ(color[0], 0.8f);
  // The default is stored for the first type only.
  EXPECT_EQ(parameterInfo(ANARI_MATERIAL,
                "matte",
                "color",
                ANARI_SAMPLER,
                "default",
                ANARI_SAMPLER),
      nullptr);

  auto *attenuation = static_cast<const float *>(parameterInfo(ANARI_MATERIAL,
      "physicallyBased",
      "attenuationDistance",
      ANARI_FLOAT32,
      "default",
      ANARI_FLOAT32));
  ASSERT_NE(attenuation, nullptr);
  EXPECT_TRUE(std::isinf(*attenuation));

  auto *id = static_cast<const uint32_t *>(parameterInfo(
      ANARI_SURFACE, "", "id", ANARI_UINT32, "default", ANARI_UINT32));
  ASSERT_NE(id, nullptr);
  EXPECT_EQ(*id, 4294967295u);
}

TEST_F(Introspection, MinimumAndMaximum)
{
  auto *minimum = static_cast<const float *>(parameterInfo(ANARI_LIGHT,
      "directional",
      "color",
      ANARI_FLOAT32_VEC3,
      "minimum",
      ANARI_FLOAT32_VEC3));
  auto *maximum = static_cast<const float *>(parameterInfo(ANARI_LIGHT,
      "directional",
      "color",
      ANARI_FLOAT32_VEC3,
      "maximum",
      ANARI_FLOAT32_VEC3));
  ASSERT_NE(minimum, nullptr);
  ASSERT_NE(maximum, nullptr);
  EXPECT_EQ(minimum[2], 0.f);
  EXPECT_EQ(maximum[2], 1.f);
  EXPECT_EQ(parameterInfo(ANARI_LIGHT,
                "directional",
                "irradiance",
                ANARI_FLOAT32,
                "minimum",
                ANARI_FLOAT32),
      nullptr);
}

TEST_F(Introspection, FrameChannelsOfImplementedExtensions)
{
  auto channels =
      strings(objectInfo(ANARI_FRAME, nullptr, "channel", ANARI_STRING_LIST));
  EXPECT_EQ(channels,
      (std::vector<std::string>{"channel.color",
          "channel.depth",
          "channel.albedo",
          "channel.objectId",
          "channel.primitiveId"}));
  EXPECT_EQ(objectInfo(ANARI_FRAME, nullptr, "channel", ANARI_STRING_LIST),
      objectInfo(ANARI_FRAME, "", "channel", ANARI_STRING_LIST))
      << "NULL and \"\" both name an object type without subtypes";
  EXPECT_EQ(objectInfo(ANARI_FRAME, nullptr, "channel", ANARI_STRING), nullptr);
  // Only frames have channels.
  EXPECT_EQ(objectInfo(ANARI_SURFACE, nullptr, "channel", ANARI_STRING_LIST),
      nullptr);

  auto params = parameterList(
      objectInfo(ANARI_FRAME, nullptr, "parameter", ANARI_PARAMETER_LIST));
  EXPECT_TRUE(hasParameter(params, "channel.albedo"));
  EXPECT_FALSE(hasParameter(params, "channel.normal"));
  EXPECT_FALSE(hasParameter(params, "accumulation"));
}

TEST_F(Introspection, DataTypeParameterValues)
{
  auto values = dataTypes(parameterInfo(ANARI_FRAME,
      nullptr,
      "channel.color",
      ANARI_DATA_TYPE,
      "value",
      ANARI_DATA_TYPE_LIST));
  EXPECT_EQ(values,
      (std::vector<int>{
          ANARI_UFIXED8_VEC4, ANARI_UFIXED8_RGBA_SRGB, ANARI_FLOAT32_VEC4}));
  EXPECT_EQ(parameterInfo(ANARI_FRAME,
                nullptr,
                "channel.color",
                ANARI_DATA_TYPE,
                "value",
                ANARI_STRING_LIST),
      nullptr);
  const ParameterDefinition *depth =
      findParameter(ANARI_FRAME, nullptr, "channel.depth");
  ASSERT_NE(depth, nullptr);
  ASSERT_EQ(depth->dataTypeValueCount, 1u);
  EXPECT_EQ(int(depth->dataTypeValues[0]), ANARI_FLOAT32);
  EXPECT_EQ(depth->values, nullptr);
}

TEST_F(Introspection, StringValuesExcludeUnimplementedAdditions)
{
  auto wrapModes = strings(parameterInfo(ANARI_SAMPLER,
      "image2D",
      "wrapMode1",
      ANARI_STRING,
      "value",
      ANARI_STRING_LIST));
  EXPECT_EQ(wrapModes,
      (std::vector<std::string>{"clampToEdge", "repeat", "mirrorRepeat"}));
  EXPECT_FALSE(contains(wrapModes, "clampToBorder"));
  EXPECT_EQ(findParameter(ANARI_SAMPLER, "image2D", "borderColor"), nullptr);

  auto *filter = static_cast<const char *>(parameterInfo(ANARI_SAMPLER,
      "image2D",
      "filter",
      ANARI_STRING,
      "default",
      ANARI_STRING));
  ASSERT_NE(filter, nullptr);
  EXPECT_STREQ(filter, "linear");
}

TEST_F(Introspection, AttributeParametersListTheAttributes)
{
  auto values = strings(parameterInfo(ANARI_MATERIAL,
      "matte",
      "color",
      ANARI_STRING,
      "value",
      ANARI_STRING_LIST));
  EXPECT_TRUE(contains(values, "attribute0"));
  EXPECT_TRUE(contains(values, "worldPosition"));
  EXPECT_EQ(values.size(), tables::kAttributeCount);
  // The FLOAT32_VEC3 form takes any value.
  EXPECT_EQ(parameterInfo(ANARI_MATERIAL,
                "matte",
                "color",
                ANARI_FLOAT32_VEC3,
                "value",
                ANARI_STRING_LIST),
      nullptr);
}

TEST_F(Introspection, ExtensionInfo)
{
  EXPECT_STREQ(static_cast<const char *>(parameterInfo(ANARI_GEOMETRY,
                   "triangle",
                   "vertex.position",
                   ANARI_ARRAY1D,
                   "extension",
                   ANARI_STRING)),
      "ANARI_KHR_GEOMETRY_TRIANGLE");
  // Core parameters come from no extension.
  EXPECT_EQ(parameterInfo(ANARI_SURFACE,
                nullptr,
                "geometry",
                ANARI_GEOMETRY,
                "extension",
                ANARI_STRING),
      nullptr);
  // A parameter one extension adds to a core object.
  EXPECT_STREQ(static_cast<const char *>(parameterInfo(ANARI_SURFACE,
                   nullptr,
                   "id",
                   ANARI_UINT32,
                   "extension",
                   ANARI_STRING)),
      "ANARI_KHR_FRAME_CHANNEL_OBJECT_ID");

  EXPECT_EQ(strings(objectInfo(
                ANARI_GEOMETRY, "triangle", "extension", ANARI_STRING_LIST)),
      std::vector<std::string>{"ANARI_KHR_GEOMETRY_TRIANGLE"});
  EXPECT_EQ(strings(objectInfo(
                ANARI_SURFACE, nullptr, "extension", ANARI_STRING_LIST)),
      std::vector<std::string>{"ANARI_KHR_FRAME_CHANNEL_OBJECT_ID"});
  EXPECT_EQ(
      strings(objectInfo(ANARI_FRAME, nullptr, "extension", ANARI_STRING_LIST)),
      (std::vector<std::string>{"ANARI_KHR_FRAME_CHANNEL_ALBEDO",
          "ANARI_KHR_FRAME_CHANNEL_OBJECT_ID",
          "ANARI_KHR_FRAME_CHANNEL_PRIMITIVE_ID"}));
  EXPECT_EQ(objectInfo(ANARI_GEOMETRY, "triangle", "extension", ANARI_STRING),
      nullptr);
}

TEST_F(Introspection, CameraDefaultSubtypeEntriesApplyToEveryCamera)
{
  const ParameterDefinition *aperture =
      findParameter(ANARI_CAMERA, "perspective", "apertureRadius");
  ASSERT_NE(aperture, nullptr);
  EXPECT_STREQ(aperture->extension, "ANARI_KHR_CAMERA_DEPTH_OF_FIELD");
  ASSERT_EQ(aperture->typeCount, 1u);
  EXPECT_EQ(int(aperture->types[0]), ANARI_FLOAT32);
  ASSERT_EQ(int(aperture->valueType), ANARI_FLOAT32);
  EXPECT_EQ(*static_cast<const float *>(aperture->defaultValue), 0.f);
  // KHR_CAMERA_STEREO is not implemented.
  EXPECT_EQ(findParameter(ANARI_CAMERA, "perspective", "stereoMode"), nullptr);
  // "default" is not itself a camera subtype.
  EXPECT_EQ(objectSubtypes(ANARI_CAMERA)[1], nullptr);
  EXPECT_STREQ(objectSubtypes(ANARI_CAMERA)[0], "perspective");
  EXPECT_EQ(
      objectInfo(ANARI_CAMERA, "default", "parameter", ANARI_PARAMETER_LIST),
      nullptr);
  auto extensions = strings(
      objectInfo(ANARI_CAMERA, "perspective", "extension", ANARI_STRING_LIST));
  EXPECT_EQ(extensions,
      (std::vector<std::string>{
          "ANARI_KHR_CAMERA_PERSPECTIVE", "ANARI_KHR_CAMERA_DEPTH_OF_FIELD"}));
}

TEST_F(Introspection, EveryRendererSubtypeUsesTheDefaultDefinitions)
{
  auto subtypes = strings(objectSubtypes(ANARI_RENDERER));
  EXPECT_EQ(subtypes,
      (std::vector<std::string>{
          "default", "pathtracer", "raycast", "ao", "debug"}));
  for (const char *renderer : kRenderers) {
    if (!renderer)
      break;
    SCOPED_TRACE(renderer);
    auto params = parameterList(objectInfo(
        ANARI_RENDERER, renderer, "parameter", ANARI_PARAMETER_LIST));
    std::pair<std::string, int> color{"background", ANARI_FLOAT32_VEC4};
    std::pair<std::string, int> image{"background", ANARI_ARRAY2D};
    EXPECT_NE(std::find(params.begin(), params.end(), color), params.end());
    EXPECT_EQ(std::find(params.begin(), params.end(), image), params.end());
    EXPECT_FALSE(hasParameter(params, "denoise"));
  }
  EXPECT_EQ(
      objectInfo(ANARI_RENDERER, "scivis", "parameter", ANARI_PARAMETER_LIST),
      nullptr);
  EXPECT_EQ(
      objectInfo(ANARI_RENDERER, nullptr, "parameter", ANARI_PARAMETER_LIST),
      nullptr);
  auto *background = static_cast<const float *>(parameterInfo(ANARI_RENDERER,
      "raycast",
      "background",
      ANARI_FLOAT32_VEC4,
      "default",
      ANARI_FLOAT32_VEC4));
  ASSERT_NE(background, nullptr);
  EXPECT_EQ(background[3], 1.f);
}

TEST_F(Introspection, UnknownOrMismatchedQueriesReturnNull)
{
  EXPECT_EQ(objectInfo(ANARI_GEOMETRY, "teapot", "description", ANARI_STRING),
      nullptr);
  EXPECT_EQ(objectInfo(ANARI_GEOMETRY, nullptr, "description", ANARI_STRING),
      nullptr);
  EXPECT_EQ(objectInfo(ANARI_SURFACE, "triangle", "description", ANARI_STRING),
      nullptr);
  EXPECT_EQ(
      objectInfo(ANARI_GEOMETRY, "triangle", "colour", ANARI_STRING), nullptr);
  EXPECT_EQ(
      objectInfo(ANARI_GEOMETRY, "triangle", nullptr, ANARI_STRING), nullptr);
  EXPECT_EQ(objectInfo(ANARI_GEOMETRY, "triangle", "description", ANARI_INT32),
      nullptr);
  EXPECT_EQ(
      objectInfo(ANARI_GEOMETRY, "triangle", "parameter", ANARI_STRING_LIST),
      nullptr);

  EXPECT_EQ(parameterInfo(ANARI_GEOMETRY,
                "triangle",
                "vertex.nonsense",
                ANARI_ARRAY1D,
                "required",
                ANARI_BOOL),
      nullptr);
  EXPECT_EQ(parameterInfo(ANARI_GEOMETRY,
                "triangle",
                "vertex.position",
                ANARI_FLOAT32_VEC3,
                "required",
                ANARI_BOOL),
      nullptr)
      << "parameterType not accepted by the parameter";
  EXPECT_EQ(parameterInfo(ANARI_GEOMETRY,
                "triangle",
                "vertex.position",
                ANARI_ARRAY1D,
                "required",
                ANARI_INT32),
      nullptr);
  EXPECT_EQ(parameterInfo(ANARI_GEOMETRY,
                "triangle",
                "vertex.position",
                ANARI_ARRAY1D,
                "softMinimum",
                ANARI_ARRAY1D),
      nullptr);
  EXPECT_EQ(parameterInfo(ANARI_GEOMETRY,
                "triangle",
                "vertex.position",
                ANARI_ARRAY1D,
                "elementType",
                ANARI_STRING_LIST),
      nullptr);
  EXPECT_EQ(parameterInfo(ANARI_GEOMETRY,
                "teapot",
                "vertex.position",
                ANARI_ARRAY1D,
                "required",
                ANARI_BOOL),
      nullptr);
  EXPECT_EQ(parameterInfo(ANARI_GEOMETRY,
                "triangle",
                nullptr,
                ANARI_ARRAY1D,
                "required",
                ANARI_BOOL),
      nullptr);
  EXPECT_EQ(findParameter(ANARI_GEOMETRY, "triangle", "nonsense"), nullptr);
  EXPECT_EQ(findParameter(ANARI_GEOMETRY, "triangle", nullptr), nullptr);
}

TEST_F(Introspection, FindParameterForValidation)
{
  const ParameterDefinition *position =
      findParameter(ANARI_GEOMETRY, "sphere", "vertex.position");
  ASSERT_NE(position, nullptr);
  EXPECT_STREQ(position->name, "vertex.position");
  EXPECT_TRUE(position->required);
  EXPECT_TRUE(position->accepts(ANARI_ARRAY1D));
  EXPECT_FALSE(position->accepts(ANARI_FLOAT32_VEC3));
  ASSERT_EQ(position->elementTypeCount, 1u);
  EXPECT_EQ(int(position->elementTypes[0]), ANARI_FLOAT32_VEC3);
  EXPECT_EQ(int(position->elementTypes[1]), ANARI_UNKNOWN);
  EXPECT_STREQ(position->extension, "ANARI_KHR_GEOMETRY_SPHERE");

  const ParameterDefinition *opacity =
      findParameter(ANARI_MATERIAL, "physicallyBased", "opacity");
  ASSERT_NE(opacity, nullptr);
  EXPECT_EQ(opacity->typeCount, 3u);
  EXPECT_TRUE(opacity->accepts(ANARI_SAMPLER));
  EXPECT_TRUE(opacity->attribute);
  EXPECT_FALSE(opacity->required);

  const ParameterDefinition *world = findParameter(ANARI_FRAME, "", "world");
  ASSERT_NE(world, nullptr);
  EXPECT_TRUE(world->required);
  EXPECT_EQ(world->extension, nullptr);

  const ParameterDefinition *alphaMode =
      findParameter(ANARI_MATERIAL, "matte", "alphaMode");
  ASSERT_NE(alphaMode, nullptr);
  ASSERT_EQ(alphaMode->valueCount, 3u);
  EXPECT_STREQ(alphaMode->values[0], "opaque");
  EXPECT_EQ(alphaMode->values[3], nullptr);
  EXPECT_EQ(findParameter(ANARI_MATERIAL, "matte", "alphaMode"), alphaMode)
      << "stable pointer";
}

TEST_F(Introspection, Properties)
{
  const PropertyDefinition *bounds =
      findProperty(ANARI_WORLD, nullptr, "bounds");
  ASSERT_NE(bounds, nullptr);
  EXPECT_EQ(int(bounds->type), ANARI_FLOAT32_BOX3);
  const PropertyDefinition *duration =
      findProperty(ANARI_FRAME, nullptr, "duration");
  ASSERT_NE(duration, nullptr);
  EXPECT_TRUE(duration->required);
  EXPECT_EQ(findProperty(ANARI_FRAME, nullptr, "nonsense"), nullptr);
  // hdAnari's convergence count, where PRISM_RENDERERS is implemented.
  EXPECT_EQ(findProperty(ANARI_FRAME, nullptr, "numSamples"), nullptr);
  const char *prism[] = {"ANARI_PRISM_RENDERERS", nullptr};
  const Catalog withPrism(prism, nullptr);
  const PropertyDefinition *samples =
      withPrism.findProperty(ANARI_FRAME, nullptr, "numSamples");
  ASSERT_NE(samples, nullptr);
  EXPECT_EQ(int(samples->type), ANARI_INT32);
  EXPECT_FALSE(samples->required);
}

TEST_F(Introspection, ConcurrentReaders)
{
  std::vector<std::thread> threads;
  std::vector<const void *> seen(8);
  for (size_t t = 0; t < seen.size(); ++t) {
    threads.emplace_back([t, &seen] {
      const void *last = nullptr;
      for (int i = 0; i < 2000; ++i) {
        last = parameterInfo(ANARI_GEOMETRY,
            "sphere",
            "radius",
            ANARI_FLOAT32,
            "default",
            ANARI_FLOAT32);
        objectSubtypes(ANARI_GEOMETRY);
        findParameter(ANARI_FRAME, nullptr, "size");
      }
      seen[t] = last;
    });
  }
  for (std::thread &t : threads)
    t.join();
  for (const void *p : seen)
    EXPECT_EQ(p, seen[0]);
}

// Catalogs built for other extension sets.

TEST(IntrospectionCatalog, NothingImplementedLeavesOnlyCore)
{
  Catalog core(nullptr, nullptr);
  EXPECT_EQ(core.deviceExtensions()[0], nullptr);
  EXPECT_EQ(core.objectSubtypes(ANARI_GEOMETRY), nullptr);
  EXPECT_EQ(strings(core.objectSubtypes(ANARI_RENDERER)),
      std::vector<std::string>{"default"});
  EXPECT_NE(
      core.objectInfo(ANARI_WORLD, nullptr, "parameter", ANARI_PARAMETER_LIST),
      nullptr);
  EXPECT_EQ(core.findParameter(ANARI_SURFACE, nullptr, "id"), nullptr);
  EXPECT_EQ(strings(core.objectInfo(
                ANARI_GROUP, nullptr, "extension", ANARI_STRING_LIST)),
      std::vector<std::string>{});
}

TEST(IntrospectionCatalog, ExtensionNamesMayOmitThePrefix)
{
  const char *implemented[] = {"KHR_GEOMETRY_CURVE", nullptr};
  Catalog catalog(implemented, nullptr);
  EXPECT_EQ(strings(catalog.objectSubtypes(ANARI_GEOMETRY)),
      std::vector<std::string>{"curve"});
}

TEST(IntrospectionCatalog, ParameterFromSeveralExtensionsMergesItsTypes)
{
  const char *implemented[] = {"ANARI_KHR_RENDERER_BACKGROUND_COLOR",
      "ANARI_KHR_RENDERER_BACKGROUND_IMAGE",
      nullptr};
  Catalog catalog(implemented, nullptr);
  const ParameterDefinition *background =
      catalog.findParameter(ANARI_RENDERER, "default", "background");
  ASSERT_NE(background, nullptr);
  ASSERT_EQ(background->typeCount, 2u);
  EXPECT_EQ(int(background->types[0]), ANARI_FLOAT32_VEC4);
  EXPECT_EQ(int(background->types[1]), ANARI_ARRAY2D);
  EXPECT_STREQ(static_cast<const char *>(catalog.parameterInfo(ANARI_RENDERER,
                   "default",
                   "background",
                   ANARI_ARRAY2D,
                   "extension",
                   ANARI_STRING)),
      "ANARI_KHR_RENDERER_BACKGROUND_IMAGE");
  EXPECT_STREQ(static_cast<const char *>(catalog.parameterInfo(ANARI_RENDERER,
                   "default",
                   "background",
                   ANARI_FLOAT32_VEC4,
                   "extension",
                   ANARI_STRING)),
      "ANARI_KHR_RENDERER_BACKGROUND_COLOR");
  EXPECT_NE(catalog.parameterInfo(ANARI_RENDERER,
                "default",
                "background",
                ANARI_ARRAY2D,
                "elementType",
                ANARI_DATA_TYPE_LIST),
      nullptr);
  EXPECT_EQ(catalog.parameterInfo(ANARI_RENDERER,
                "default",
                "background",
                ANARI_FLOAT32_VEC4,
                "elementType",
                ANARI_DATA_TYPE_LIST),
      nullptr);
  auto params = parameterList(catalog.objectInfo(
      ANARI_RENDERER, "default", "parameter", ANARI_PARAMETER_LIST));
  EXPECT_EQ(std::count_if(params.begin(),
                params.end(),
                [](auto &p) { return p.first == "background"; }),
      2);
}

TEST(IntrospectionCatalog, WildcardSubtypeParametersReachEverySubtype)
{
  const char *implemented[] = {"ANARI_KHR_INSTANCE_TRANSFORM",
      "ANARI_KHR_INSTANCE_MOTION_TRANSFORM",
      "ANARI_KHR_INSTANCE_TRANSFORM_ARRAY",
      "ANARI_KHR_FRAME_CHANNEL_INSTANCE_ID",
      nullptr};
  Catalog catalog(implemented, nullptr);
  const ParameterDefinition *motionId =
      catalog.findParameter(ANARI_INSTANCE, "motionTransform", "id");
  ASSERT_NE(motionId, nullptr);
  EXPECT_STREQ(motionId->extension, "ANARI_KHR_FRAME_CHANNEL_INSTANCE_ID");
  // transform: UINT32 id from the channel, ARRAY1D id from transform arrays.
  const ParameterDefinition *id =
      catalog.findParameter(ANARI_INSTANCE, "transform", "id");
  ASSERT_NE(id, nullptr);
  EXPECT_TRUE(id->accepts(ANARI_UINT32));
  EXPECT_TRUE(id->accepts(ANARI_ARRAY1D));
  const ParameterDefinition *transform =
      catalog.findParameter(ANARI_INSTANCE, "transform", "transform");
  ASSERT_NE(transform, nullptr);
  EXPECT_TRUE(transform->accepts(ANARI_FLOAT32_MAT4));
  EXPECT_TRUE(transform->accepts(ANARI_ARRAY1D));
  ASSERT_EQ(int(transform->valueType), ANARI_FLOAT32_MAT4);
  EXPECT_EQ(static_cast<const float *>(transform->defaultValue)[15], 1.f);
  EXPECT_EQ(strings(catalog.objectInfo(
                ANARI_INSTANCE, "transform", "extension", ANARI_STRING_LIST)),
      (std::vector<std::string>{"ANARI_KHR_INSTANCE_TRANSFORM",
          "ANARI_KHR_INSTANCE_TRANSFORM_ARRAY",
          "ANARI_KHR_FRAME_CHANNEL_INSTANCE_ID"}));
}

TEST(IntrospectionCatalog, ValueAddingExtensions)
{
  const char *implemented[] = {"ANARI_EXT_SAMPLER_COMPRESSED_IMAGE2D",
      "ANARI_EXT_SAMPLER_COMPRESSED_FORMAT_ETC",
      "ANARI_EXT_SAMPLER_COMPRESSED_FORMAT_ETC2",
      "ANARI_KHR_SAMPLER_IMAGE2D",
      "ANARI_KHR_SAMPLER_IMAGExD_CLAMP_TO_BORDER",
      "ANARI_KHR_SPATIAL_FIELD_STRUCTURED_REGULAR",
      nullptr};
  Catalog catalog(implemented, nullptr);
  auto formats = strings(catalog.parameterInfo(ANARI_SAMPLER,
      "compressedImage2D",
      "format",
      ANARI_STRING,
      "value",
      ANARI_STRING_LIST));
  // ETC and ETC2 add the same six formats; each is listed once.
  EXPECT_EQ(formats.size(), 6u);
  EXPECT_TRUE(contains(formats, "ETC2_R8G8B8"));
  EXPECT_FALSE(contains(formats, "BC7"));

  auto wrapModes = strings(catalog.parameterInfo(ANARI_SAMPLER,
      "image2D",
      "wrapMode2",
      ANARI_STRING,
      "value",
      ANARI_STRING_LIST));
  EXPECT_TRUE(contains(wrapModes, "clampToBorder"));
  EXPECT_NE(
      catalog.findParameter(ANARI_SAMPLER, "image2D", "borderColor"), nullptr);
  // Filter "cubic" needs KHR_SPATIAL_FIELD_STRUCTURED_REGULAR_FILTER_CUBIC.
  auto filters = strings(catalog.parameterInfo(ANARI_SPATIAL_FIELD,
      "structuredRegular",
      "filter",
      ANARI_STRING,
      "value",
      ANARI_STRING_LIST));
  EXPECT_EQ(filters, (std::vector<std::string>{"nearest", "linear"}));

  // Without a format extension the format list exists but is empty.
  const char *noFormats[] = {"ANARI_EXT_SAMPLER_COMPRESSED_IMAGE2D", nullptr};
  Catalog bare(noFormats, nullptr);
  const ParameterDefinition *format =
      bare.findParameter(ANARI_SAMPLER, "compressedImage2D", "format");
  ASSERT_NE(format, nullptr);
  ASSERT_NE(format->values, nullptr);
  EXPECT_EQ(format->valueCount, 0u);
  EXPECT_EQ(format->values[0], nullptr);
}

// With every extension implemented, every object of the tables is reachable
// and every parameter the "parameter" list reports answers its own queries.
TEST(IntrospectionCatalog, EverythingImplementedIsConsistent)
{
  std::vector<const char *> all = allExtensions();
  Catalog catalog(all.data(), nullptr);
  EXPECT_EQ(
      strings(catalog.deviceExtensions()).size(), tables::kExtensionCount);
  size_t parameters = 0;
  for (size_t i = 0; i < tables::kObjectCount; ++i) {
    const tables::ObjectEntry &object = tables::kObjects[i];
    SCOPED_TRACE(std::string(anari::toString(object.type)) + " "
                 + (object.subtype ? object.subtype : ""));
    if (object.subtype) {
      EXPECT_TRUE(contains(
          strings(catalog.objectSubtypes(object.type)), object.subtype));
    }
    auto list = parameterList(catalog.objectInfo(
        object.type, object.subtype, "parameter", ANARI_PARAMETER_LIST));
    EXPECT_FALSE(list.empty());
    std::set<std::pair<std::string, int>> unique(list.begin(), list.end());
    EXPECT_EQ(unique.size(), list.size()) << "each name/type once";
    for (const auto &[name, type] : list) {
      SCOPED_TRACE(name);
      ++parameters;
      EXPECT_NE(catalog.parameterInfo(object.type,
                    object.subtype,
                    name.c_str(),
                    type,
                    "required",
                    ANARI_BOOL),
          nullptr);
      const ParameterDefinition *definition =
          catalog.findParameter(object.type, object.subtype, name.c_str());
      ASSERT_NE(definition, nullptr);
      EXPECT_TRUE(definition->accepts(type));
      EXPECT_FALSE(definition->required && definition->defaultValue)
          << "the spec forbids a default on a required parameter";
    }
  }
  EXPECT_GT(parameters, 400u);
}

} // namespace
} // namespace prism::introspection
