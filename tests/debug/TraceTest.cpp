// The trace format reads back what it writes, and a trace of a program using
// every kind of call replays on prism to the same image.
#include "DebugLayerTestSupport.h"
#include "trace/TraceFormat.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>

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

// A device of the layer writing its trace to `path` (NULL on failure).
ANARIDevice newTracedDevice(ANARILibrary library, const std::string &path)
{
  std::remove(path.c_str());
  if (setenv("ANARI_DEBUG_TRACE", path.c_str(), 1) != 0)
    return nullptr;
  ANARIDevice device = anariNewDevice(library, "default");
  unsetenv("ANARI_DEBUG_TRACE");
  return device;
}

std::string readFile(const std::string &path)
{
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The trace of `program` run on a device of the layer ("" on failure).
std::string traceOf(
    ANARILibrary library, const std::string &path, void (*program)(ANARIDevice))
{
  ANARIDevice device = newTracedDevice(library, path);
  if (!device)
    return {};
  program(device);
  anariRelease(device, device);
  return readFile(path);
}

// Every one of `runs` (lines, or lines in a row) is in the trace `text`.
void expectInTrace(
    const std::string &text, std::initializer_list<const char *> runs)
{
  for (const char *run : runs)
    EXPECT_NE(text.find(run), std::string::npos) << run << "\n" << text;
}

} // namespace

TEST_F(DebugLayerTest, TraceOfEveryKindOfCallReplays)
{
  const std::string path = "debug-layer-test.trace";
  const std::string text = traceOf(m_library, path, renderTriangle);
  EXPECT_TRUE(silent());
  expectInTrace(text,
      {"ParameterArray o1 \"vertex.position\"",
          "ArrayData o2 @",
          "Unset o1 \"name\"",
          "Retain o",
          "Array o5 ARRAY1D SURFACE [1 0 0] [o4]",
          "ArrayData o8 [o7]",
          "Map o11 \"channel.color\" 24 16 UFIXED8_RGBA_SRGB h",
          "Release device"});

#ifdef PRISM_ANARI_REPLAY
  const std::string command =
      std::string(PRISM_ANARI_REPLAY) + " " + path + " > " + path + ".out";
  EXPECT_EQ(std::system(command.c_str()), 0) << readFile(path + ".out");
  EXPECT_NE(readFile(path + ".out")
                .find("1 frame(s) the same bit for bit, 0 "
                      "different"),
      std::string::npos);
#endif
}

namespace {

// A program that misuses the API: every call below but the creations,
// releases and the first unmap is reported by the layer.
void misuse(ANARIDevice d)
{
  ANARIGeometry released = anariNewGeometry(d, "sphere");
  anariRelease(d, released);
  const float radius = 0.5f;
  anariSetParameter(d, released, "radius", ANARI_FLOAT32, &radius);
  ANARISurface surface = anariNewSurface(d);
  auto foreign = (ANARIGeometry)uintptr_t(0x5eed1234);
  anariSetParameter(d, surface, "geometry", ANARI_GEOMETRY, &foreign);
  anariCommitParameters(d, (ANARIObject)foreign);
  ANARIMaterial material = anariNewMaterial(d, "matte");
  const int32_t notAColor = 3;
  anariSetParameter(d, material, "color", ANARI_INT32, &notAColor);
  anariCommitParameters(d, material);
  anariCommitParameters(d, surface); // no geometry
  ANARIArray1D array =
      anariNewArray1D(d, nullptr, nullptr, nullptr, ANARI_FLOAT32, 4);
  std::memset(anariMapArray(d, array), 0, 4 * sizeof(float));
  anariUnmapArray(d, array);
  anariUnmapArray(d, array);
  for (ANARIObject o :
      {(ANARIObject)array, (ANARIObject)material, (ANARIObject)surface})
    anariRelease(d, o);
}

#ifdef PRISM_ANARI_REPLAY
// anari-replay --check-reports's exit status on `path`, its output in
// `output`. Each trace has its own output file: ctest runs these tests
// side by side in one directory.
int replayReports(const std::string &path, std::string &output)
{
  const std::string out = path + ".reports.out";
  const std::string command = std::string(PRISM_ANARI_REPLAY) + " " + path
                              + " --check-reports > " + out + " 2>&1";
  const int status = std::system(command.c_str());
  output = readFile(out);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The `n` reports of the trace at `path` are replayed the same.
::testing::AssertionResult sameReportsReplayed(const std::string &path, int n)
{
  std::string output;
  const int status = replayReports(path, output);
  const std::string same = std::to_string(n) + " report(s) recorded, "
                           + std::to_string(n) + " replayed: the same";
  if (status == 0 && output.find(same) != std::string::npos)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "exit " << status << ":\n" << output;
}

// Without --check-reports (refused calls left out), the trace replays.
::testing::AssertionResult replaysWithoutTheLayer(const std::string &path)
{
  const std::string command =
      std::string(PRISM_ANARI_REPLAY) + " " + path + " > " + path + ".out 2>&1";
  if (std::system(command.c_str()) == 0)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << readFile(path + ".out");
}
#endif

} // namespace

TEST_F(DebugLayerTest, TraceOfMisuseReplaysToTheSameReports)
{
  const std::string path = "debug-layer-misuse.trace";
  const std::string text = traceOf(m_library, path, misuse);
  size_t reported = 0;
  for (auto &m : takeProblems(m_status))
    reported += fromLayer(m) ? 1 : 0;
  EXPECT_EQ(reported, 7u);

  size_t recorded = 0;
  for (size_t at = text.find("\nReport "); at != std::string::npos;
       at = text.find("\nReport ", at + 1))
    ++recorded;
  EXPECT_EQ(recorded, reported) << text;
  expectInTrace(text,
      {"Refused Set o1 \"radius\" FLOAT32",
          "Report ERROR INVALID_ARGUMENT \"anariSetParameter(): object "
          "handle is geometry sphere #1, used after its release",
          "Refused Set o2 \"geometry\" GEOMETRY foreign",
          "Refused Commit foreign\nReport ERROR INVALID_ARGUMENT "
          "\"anariCommitParameters(): object handle 0x? is not",
          "Set o3 \"color\" INT32",
          "Commit o2\nReport ERROR INVALID_OPERATION",
          "ArrayData o4 @",
          "Refused UnmapArray o4\nReport ERROR INVALID_OPERATION"});
  EXPECT_EQ(text.find("0x5eed"), std::string::npos) << text;

#ifdef PRISM_ANARI_REPLAY
  EXPECT_TRUE(sameReportsReplayed(path, 7));
  std::string output;

  // Without the misuse of a released object, the reports differ.
  const std::string altered = "debug-layer-misuse-altered.trace";
  {
    std::ofstream out(altered);
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("Refused Set o1 ", 0) != 0)
        out << line << "\n";
    }
    std::ofstream(altered + ".bin", std::ios::binary)
        << std::ifstream(path + ".bin", std::ios::binary).rdbuf();
  }
  EXPECT_EQ(replayReports(altered, output), 3) << output;
  EXPECT_NE(output.find("report 1: recorded Report ERROR"), std::string::npos)
      << output;

  // Nor may a report be dropped from the trace.
  {
    std::ofstream out(altered);
    std::istringstream in(text);
    bool dropped = false;
    for (std::string line; std::getline(in, line);) {
      if (!dropped && line.rfind("Report ", 0) == 0
          && line.find("UnmapArray") != std::string::npos)
        dropped = true;
      else
        out << line << "\n";
    }
  }
  EXPECT_EQ(replayReports(altered, output), 3) << output;

  // Without --check-reports, the refused calls are left out: the wrapped
  // device alone never sees them.
  EXPECT_TRUE(replaysWithoutTheLayer(path));
#endif
}

namespace {

// Misuse of mapping, frames and creation: each call is refused by the
// layer (and one object is leaked, created on a known trace line).
void misuseMapsFramesAndCreation(ANARIDevice d)
{
  anariNewGeometry(d, nullptr);
  anariNewArray1D(d, nullptr, nullptr, nullptr, ANARI_FLOAT32, 0);
  ANARIArray1D array =
      anariNewArray1D(d, nullptr, nullptr, nullptr, ANARI_FLOAT32, 4);
  std::memset(anariMapArray(d, array), 0, 4 * sizeof(float));
  anariMapArray(d, array);
  anariUnmapArray(d, array);

  ANARIRenderer renderer = anariNewRenderer(d, "default");
  uint64_t stride = 0;
  std::memset(anariMapParameterArray2D(
                  d, renderer, "background", ANARI_FLOAT32_VEC4, 1, 1, &stride),
      0,
      4 * sizeof(float));
  const float red[4] = {1, 0, 0, 1};
  anariSetParameter(d, renderer, "background", ANARI_FLOAT32_VEC4, red);
  anariMapParameterArray2D(
      d, renderer, "background", ANARI_FLOAT32_VEC4, 1, 1, &stride);
  anariUnmapParameterArray(d, renderer, "background");
  anariUnmapParameterArray(d, renderer, "background");

  ANARIFrame frame = anariNewFrame(d);
  uint32_t w = 0, h = 0;
  ANARIDataType type = ANARI_UNKNOWN;
  anariMapFrame(d, frame, "channel.color", &w, &h, &type);
  anariUnmapFrame(d, frame, "channel.color");
  auto foreign = (ANARIFrame)uintptr_t(0x5eed1234);
  anariRenderFrame(d, foreign);
  anariFrameReady(d, foreign, ANARI_WAIT);
  anariDiscardFrame(d, foreign);
  int value = 0;
  anariGetProperty(
      d, foreign, "duration", ANARI_FLOAT32, &value, sizeof(value), ANARI_WAIT);

  ANARIGeometry leaked = anariNewGeometry(d, "sphere");
  anariSetParameter(d, leaked, "name", ANARI_STRING, "ball");
  for (ANARIObject o :
      {(ANARIObject)frame, (ANARIObject)renderer, (ANARIObject)array})
    anariRelease(d, o);
}

} // namespace

TEST_F(DebugLayerTest, TraceOfRefusedMapFrameAndCreationCallsReplays)
{
  const std::string path = "debug-layer-refused.trace";
  const std::string text =
      traceOf(m_library, path, misuseMapsFramesAndCreation);
  std::vector<std::string> reported;
  for (auto &m : takeProblems(m_status)) {
    EXPECT_TRUE(fromLayer(m)) << m.text; // prism never saw a refused call
    reported.push_back(m.text);
  }
  EXPECT_EQ(reported.size(), 14u);
  expectInTrace(text,
      {"Refused New - GEOMETRY\nReport ERROR",
          "Refused Array - ARRAY1D FLOAT32 [0 0 0] -\nReport ERROR",
          "MapArray o1\n",
          "Refused MapArray o1\nReport ERROR INVALID_OPERATION",
          "MapParameterArray o2 \"background\" ARRAY2D FLOAT32_VEC4 [1 1 0]\n",
          "Refused Set o2 \"background\" FLOAT32_VEC4",
          "Refused MapParameterArray o2 \"background\" ARRAY2D FLOAT32_VEC4 "
          "[1 1 0]\nReport ERROR INVALID_OPERATION",
          "ParameterArray o2 \"background\" ARRAY2D FLOAT32_VEC4 [1 1 0] @",
          "Refused UnmapParameterArray o2 \"background\"\nReport ERROR",
          "Refused Map o3 \"channel.color\"\nReport ERROR INVALID_OPERATION",
          "Refused Unmap o3 \"channel.color\"\nReport ERROR",
          "Refused Render foreign\nReport ERROR INVALID_ARGUMENT",
          "Refused Ready foreign WAIT\nReport ERROR",
          "Refused Discard foreign\nReport ERROR",
          "Refused Property foreign \"duration\" FLOAT32 4 WAIT\nReport"});

  // The leak names the trace line that created the object.
  const size_t created = text.find("New o4 GEOMETRY \"sphere\"\n");
  ASSERT_NE(created, std::string::npos) << text;
  const auto line = 1 + std::count(text.begin(), text.begin() + created, '\n');
  ASSERT_FALSE(reported.empty());
  EXPECT_NE(reported.back().find("leaked geometry sphere #4 \"ball\", created "
                                 "by anariNewGeometry (API call 20, trace line "
                                 + std::to_string(line) + ")"),
      std::string::npos)
      << reported.back();

#ifdef PRISM_ANARI_REPLAY
  EXPECT_TRUE(sameReportsReplayed(path, 14));
  // Without --check-reports the refused calls are left out, and the
  // parameter array is mapped by its own line, written at its unmap.
  EXPECT_TRUE(replaysWithoutTheLayer(path));
#endif
}

#ifdef PRISM_ANARI_REPLAY
namespace {

// anari-replay on a trace written here (and its side file of `sideBytes`
// bytes): its exit status (-1 for a signal: a crash), its output in
// `output`.
int replayCrafted(const std::string &name,
    const std::string &text,
    size_t sideBytes,
    const char *options,
    std::string &output)
{
  const std::string path = "untrusted-" + name + ".trace";
  std::ofstream(path) << text;
  std::ofstream side(path + ".bin", std::ios::binary);
  side << std::string(sideBytes, '\x3f');
  side.close();
  const std::string out = path + ".out";
  const std::string command = std::string(PRISM_ANARI_REPLAY) + " " + path + " "
                              + options + " > " + out + " 2>&1";
  const int status = std::system(command.c_str());
  output = readFile(out);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

} // namespace

// Each device of a process writes its own trace (FILE, FILE.2, ...), also
// when the program unloads the layer's library and loads it again: the
// second device's trace must not overwrite the first's.
TEST(TraceNumbering, ALibraryLoadedAgainKeepsCounting)
{
  const std::string path = "reloaded-library.trace";
  auto traces = [&] {
    std::vector<std::string> found;
    for (int n = 1; n <= 64; n++) {
      const std::string name = n == 1 ? path : path + "." + std::to_string(n);
      if (std::ifstream(name).good())
        found.push_back(name);
    }
    return found;
  };
  for (const std::string &old : traces())
    std::remove(old.c_str());
  ASSERT_EQ(setenv("ANARI_DEBUG_TRACE", path.c_str(), 1), 0);
  for (int load = 0; load < 2; load++) {
    ANARILibrary library = anariLoadLibrary("debug", nullptr, nullptr);
    ANARIDevice device = library ? anariNewDevice(library, "default") : nullptr;
    EXPECT_NE(device, nullptr) << "load " << load;
    if (device)
      anariRelease(device, device);
    if (library)
      anariUnloadLibrary(library);
  }
  unsetenv("ANARI_DEBUG_TRACE"); // before any assertion can return
  const std::vector<std::string> written = traces();
  ASSERT_EQ(written.size(), 2u) << "two devices, two traces";
  for (const std::string &name : written)
    expectInTrace(readFile(name), {"\nDevice \"default\""});
}

// Sizes, counts and handles in a trace are checked before use: each of
// these once overflowed the heap, threw out of main or let the layer read
// past a buffer. Each is now one error (exit 1) naming the line.
TEST(ReplayUntrustedTrace, SizesAndHandlesAreCheckedBeforeUse)
{
  const std::string device = "Device \"default\" \"prism\"\n";
  struct Case
  {
    const char *name;
    std::string text;
    size_t sideBytes;
    const char *options;
    const char *said;
  };
  const Case cases[] = {
      {"array-data-past-array",
          device + "Array o1 ARRAY1D FLOAT32 [4 0 0] -\nArrayData o1 @0:4096\n",
          4096,
          "",
          "line 3: ArrayData o1: 4096 bytes of data for an array of 16"},
      {"parameter-array-past-array",
          device
              + "New o1 RENDERER \"default\"\n"
                "ParameterArray o1 \"background\" ARRAY1D FLOAT32 [2 0 0] "
                "@0:4096\n",
          4096,
          "",
          "line 3: ParameterArray: 1024 items of data for 2 mapped"},
      {"property-of-2-to-the-62",
          device
              + "Property device \"version\" INT32 4611686018427387904 WAIT\n",
          0,
          "",
          "line 2: Property: a size of 4611686018427387904 bytes is more than"},
      {"array-items-past-data",
          device + "Array o1 ARRAY1D FLOAT32 [1000000 0 0] @0:16\n",
          16,
          "--check-reports",
          "line 2: Array o1: its 4000000 bytes of items are more than its "
          "data's 16"},
      {"used-after-release",
          device + "New o1 GEOMETRY \"sphere\"\nRelease o1\nCommit o1\n",
          0,
          "",
          "line 4: 'o1' used after its release"},
      {"negative-count",
          device + "Array o1 ARRAY1D FLOAT32 [-1 0 0] -\n",
          0,
          "",
          "line 2: a number expected, not '-1'"},
      {"array-size-overflows",
          device
              + "Array o1 ARRAY2D FLOAT64_VEC4 [4294967296 4294967296 0] -\n",
          0,
          "",
          "line 2: the array's size overflows 64 bits"},
      {"second-device",
          device + "Release device\n" + device + "New o1 GEOMETRY \"sphere\"\n",
          0,
          "",
          "line 3: a second 'Device'"},
  };
  for (const Case &c : cases) {
    std::string output;
    EXPECT_EQ(replayCrafted(c.name, c.text, c.sideBytes, c.options, output), 1)
        << c.name << ":\n"
        << output;
    EXPECT_NE(output.find(c.said), std::string::npos) << c.name << ":\n"
                                                      << output;
  }
}
#endif
