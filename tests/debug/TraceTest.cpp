// The trace format reads back what it writes, and a trace of a program using
// every kind of call replays on prism to the same image.
#include "DebugLayerTestSupport.h"
#include "trace/TraceFormat.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

using namespace prism;

TEST(TraceFormat, ValuesReadBackToTheSameBits)
{
  const float floats[3] = {0.1f,
      -std::numeric_limits<float>::denorm_min(),
      std::numeric_limits<float>::max()};
  const uint32_t ints[2] = {7u, 0xfffffffeu};
  const double one = 1.0 / 3.0;
  struct Case
  {
    ANARIDataType type;
    const void *value;
  } cases[] = {{ANARI_FLOAT32_VEC3, floats},
      {ANARI_UINT32_VEC2, ints},
      {ANARI_FLOAT64, &one},
      {ANARI_UFIXED8_VEC4, ints}};
  for (const Case &c : cases) {
    const std::string text = trace::encodeValue(c.type, c.value);
    std::vector<trace::Token> tokens;
    std::string error;
    ASSERT_TRUE(trace::tokenize(text, tokens, error)) << error;
    std::vector<std::string> components;
    for (size_t i = 1; i + 1 < tokens.size(); ++i)
      components.push_back(tokens[i].text);
    std::vector<unsigned char> bytes;
    ASSERT_TRUE(trace::decodeValue(c.type, components, bytes)) << text;
    EXPECT_EQ(std::memcmp(bytes.data(), c.value, bytes.size()), 0) << text;
  }
  std::vector<unsigned char> bytes;
  EXPECT_FALSE(trace::decodeValue(ANARI_FLOAT32_VEC2, {"1"}, bytes));
  EXPECT_FALSE(trace::decodeValue(ANARI_UINT32, {"x0102"}, bytes));
}

TEST(TraceFormat, StringsAndNamesRoundTrip)
{
  const std::string text = "say \"hi\"\t\\ # not a comment\n";
  std::vector<trace::Token> tokens;
  std::string error;
  ASSERT_TRUE(trace::tokenize(
      "Set o1 " + trace::quote(text) + " [1 2] # comment", tokens, error));
  ASSERT_EQ(tokens.size(), 7u);
  EXPECT_EQ(tokens[2].kind, trace::Token::kString);
  EXPECT_EQ(tokens[2].text, text);
  EXPECT_EQ(tokens[3].kind, trace::Token::kOpen);
  EXPECT_FALSE(trace::tokenize("Set \"open", tokens, error));

  ANARIDataType type;
  ASSERT_TRUE(trace::typeFromName(trace::typeName(ANARI_FLOAT32_VEC3), type));
  EXPECT_EQ(type, ANARI_FLOAT32_VEC3);
  EXPECT_FALSE(trace::typeFromName("FLOAT33", type));
}

namespace {

const float kTriangle[9] = {-1, -1, 0, 1, -1, 0, 0, 1, 0};

// A frame of one triangle, built with mapped parameter arrays, a managed
// array written by mapping, object arrays, retain and unset.
void renderTriangle(ANARIDevice d)
{
  ANARIGeometry geometry = anariNewGeometry(d, "triangle");
  uint64_t stride = 0;
  auto *positions = (float *)anariMapParameterArray1D(
      d, geometry, "vertex.position", ANARI_FLOAT32_VEC3, 3, &stride);
  for (int i = 0; i < 3; ++i)
    std::memcpy((char *)positions + i * stride, kTriangle + 3 * i, 12);
  anariUnmapParameterArray(d, geometry, "vertex.position");
  ANARIArray1D index =
      anariNewArray1D(d, nullptr, nullptr, nullptr, ANARI_UINT32_VEC3, 1);
  auto *indices = (uint32_t *)anariMapArray(d, index);
  indices[0] = 0, indices[1] = 1, indices[2] = 2;
  anariUnmapArray(d, index);
  anariSetParameter(d, geometry, "primitive.index", ANARI_ARRAY1D, &index);
  anariSetParameter(d, geometry, "name", ANARI_STRING, "the \"triangle\"");
  anariUnsetParameter(d, geometry, "name");
  anariCommitParameters(d, geometry);

  ANARIMaterial material = anariNewMaterial(d, "matte");
  const float red[3] = {0.8f, 0.1f, 0.1f};
  anariSetParameter(d, material, "color", ANARI_FLOAT32_VEC3, red);
  anariCommitParameters(d, material);
  ANARISurface surface = anariNewSurface(d);
  anariSetParameter(d, surface, "geometry", ANARI_GEOMETRY, &geometry);
  anariSetParameter(d, surface, "material", ANARI_MATERIAL, &material);
  anariCommitParameters(d, surface);
  ANARIArray1D surfaces =
      anariNewArray1D(d, &surface, nullptr, nullptr, ANARI_SURFACE, 1);
  ANARIWorld world = anariNewWorld(d);
  anariSetParameter(d, world, "surface", ANARI_ARRAY1D, &surfaces);
  ANARILight light = anariNewLight(d, "directional");
  anariCommitParameters(d, light);
  ANARIArray1D lights =
      anariNewArray1D(d, nullptr, nullptr, nullptr, ANARI_LIGHT, 1);
  *(ANARILight *)anariMapArray(d, lights) = light;
  anariUnmapArray(d, lights);
  anariSetParameter(d, world, "light", ANARI_ARRAY1D, &lights);
  anariCommitParameters(d, world);

  ANARICamera camera = anariNewCamera(d, "perspective");
  const float eye[3] = {0, 0, 3};
  anariSetParameter(d, camera, "position", ANARI_FLOAT32_VEC3, eye);
  anariCommitParameters(d, camera);
  ANARIRenderer renderer = anariNewRenderer(d, "default");
  anariRetain(d, renderer);
  anariRelease(d, renderer);
  anariCommitParameters(d, renderer);
  ANARIFrame frame = anariNewFrame(d);
  const uint32_t size[2] = {24, 16};
  const ANARIDataType color = ANARI_UFIXED8_RGBA_SRGB;
  anariSetParameter(d, frame, "world", ANARI_WORLD, &world);
  anariSetParameter(d, frame, "camera", ANARI_CAMERA, &camera);
  anariSetParameter(d, frame, "renderer", ANARI_RENDERER, &renderer);
  anariSetParameter(d, frame, "size", ANARI_UINT32_VEC2, size);
  anariSetParameter(d, frame, "channel.color", ANARI_DATA_TYPE, &color);
  anariCommitParameters(d, frame);
  for (int i = 0; i < 2; ++i) {
    anariRenderFrame(d, frame);
    anariFrameReady(d, frame, ANARI_WAIT);
  }
  uint32_t w, h;
  ANARIDataType type;
  anariMapFrame(d, frame, "channel.color", &w, &h, &type);
  anariUnmapFrame(d, frame, "channel.color");
  for (ANARIObject o : {(ANARIObject)frame,
           (ANARIObject)renderer,
           (ANARIObject)camera,
           (ANARIObject)world,
           (ANARIObject)lights,
           (ANARIObject)light,
           (ANARIObject)surfaces,
           (ANARIObject)surface,
           (ANARIObject)material,
           (ANARIObject)index,
           (ANARIObject)geometry})
    anariRelease(d, o);
}

std::string readFile(const std::string &path)
{
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

} // namespace

TEST_F(DebugLayerTest, TraceOfEveryKindOfCallReplays)
{
  const std::string path = "debug-layer-test.trace";
  std::remove(path.c_str());
  ASSERT_EQ(setenv("ANARI_DEBUG_TRACE", path.c_str(), 1), 0);
  ANARIDevice device = anariNewDevice(m_library, "default");
  unsetenv("ANARI_DEBUG_TRACE");
  ASSERT_NE(device, nullptr);
  renderTriangle(device);
  anariRelease(device, device);
  EXPECT_TRUE(silent());

  const std::string text = readFile(path);
  for (const char *call : {"ParameterArray o1 \"vertex.position\"",
           "ArrayData o2 @",
           "Unset o1 \"name\"",
           "Retain o",
           "Array o5 ARRAY1D SURFACE [1 0 0] [o4]",
           "ArrayData o8 [o7]",
           "Map o11 \"channel.color\" 24 16 UFIXED8_RGBA_SRGB h",
           "Release device"})
    EXPECT_NE(text.find(call), std::string::npos) << call << "\n" << text;

#ifdef PRISM_ANARI_REPLAY
  const std::string command =
      std::string(PRISM_ANARI_REPLAY) + " " + path + " > replay.out";
  EXPECT_EQ(std::system(command.c_str()), 0) << readFile("replay.out");
  EXPECT_NE(readFile("replay.out")
                .find("1 frame(s) the same bit for bit, 0 "
                      "different"),
      std::string::npos);
#endif
}
