#include "RenderTest.h"

#include "ImageMetrics.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>

#include "anari/frontend/type_utility.h"

namespace {

namespace fs = std::filesystem;
using namespace prism::image;

constexpr uint32_t kMaxSize = 256;

// One line of tolerances.txt: `<name> <metric> <limit>  # reason`.
struct ToleranceCheck
{
  std::string metric; // as written, for messages
  enum class Kind { Rmse, Max, Psnr, Fraction } kind;
  double pixelThreshold; // Fraction: a pixel differs by more than this
  double limit;
  std::string reason;
  int line;
};

struct ToleranceTable
{
  std::map<std::string, std::vector<ToleranceCheck>> checks;
  std::string error; // empty when the whole file parsed

  const std::vector<ToleranceCheck> &checksFor(const std::string &name) const
  {
    auto found = checks.find(name);
    return found != checks.end() ? found->second : checks.at("default");
  }
};

bool parseLimit(const std::string &text, double &value)
{
  char *end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && *end == '\0' && std::isfinite(value) && value >= 0;
}

std::string trim(const std::string &text)
{
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos)
    return {};
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

// Whether `name` is a registered test ("Scene.Renderer") or one of its
// extra images ("Scene.Renderer.something").
bool namesATest(const std::string &name)
{
  auto *unitTest = ::testing::UnitTest::GetInstance();
  for (int i = 0; i < unitTest->total_test_suite_count(); i++) {
    const auto *suite = unitTest->GetTestSuite(i);
    for (int j = 0; j < suite->total_test_count(); j++) {
      const std::string test =
          std::string(suite->name()) + "." + suite->GetTestInfo(j)->name();
      if (name == test || name.starts_with(test + "."))
        return true;
    }
  }
  return false;
}

ToleranceTable parseTolerances(const std::string &path)
{
  ToleranceTable table;
  std::ifstream file(path);
  if (!file) {
    table.error = "cannot open the tolerance table '" + path + "'";
    return table;
  }
  std::string text;
  for (int line = 1; std::getline(file, text); line++) {
    const std::string where = path + ":" + std::to_string(line) + ": ";
    const auto hash = text.find('#');
    const std::string reason =
        hash == std::string::npos ? std::string() : trim(text.substr(hash + 1));
    std::istringstream fields(text.substr(0, hash));
    std::string name, metric, limitText, extra;
    if (!(fields >> name))
      continue; // blank or comment-only
    if (!(fields >> metric >> limitText) || (fields >> extra)) {
      table.error = where + "expected '<name> <metric> <limit>  # reason'";
      return table;
    }
    if (reason.empty()) {
      table.error = where + "every tolerance needs a '# reason'";
      return table;
    }
    ToleranceCheck check{
        metric, ToleranceCheck::Kind::Rmse, 0, 0, reason, line};
    if (!parseLimit(limitText, check.limit)) {
      table.error = where + "bad limit '" + limitText + "'";
      return table;
    }
    if (metric == "rmse") {
      check.kind = ToleranceCheck::Kind::Rmse;
    } else if (metric == "max") {
      check.kind = ToleranceCheck::Kind::Max;
    } else if (metric == "psnr") {
      check.kind = ToleranceCheck::Kind::Psnr;
    } else if (metric.starts_with("fraction>")
               && parseLimit(metric.substr(9), check.pixelThreshold)) {
      check.kind = ToleranceCheck::Kind::Fraction;
    } else {
      table.error = where + "unknown metric '" + metric
                    + "' (rmse, max, psnr or fraction>T)";
      return table;
    }
    if (name != "default" && !namesATest(name)) {
      table.error = where + "'" + name + "' names no render test (stale line?)";
      return table;
    }
    table.checks[name].push_back(check);
  }
  if (!table.checks.count("default"))
    table.error = path + ": no 'default' line";
  return table;
}

// Parsed once per process; every test shares the same table.
const ToleranceTable &tolerances()
{
  static const ToleranceTable table = parseTolerances(PRISM_RENDER_TOLERANCES);
  return table;
}

bool updatingReferences()
{
  const char *value = std::getenv("PRISM_UPDATE_REFERENCES");
  return value && *value && std::strcmp(value, "0") != 0;
}

fs::path outputDirectory()
{
  const char *value = std::getenv("PRISM_RENDER_OUTPUT_DIR");
  return value && *value ? fs::path(value) : fs::current_path();
}

// The value of one check's metric, and whether it is within the limit.
std::pair<double, bool> evaluate(
    const ToleranceCheck &check, const Image &rendered, const Image &reference)
{
  switch (check.kind) {
  case ToleranceCheck::Kind::Rmse: {
    const double value = rmse(rendered, reference);
    return {value, value <= check.limit};
  }
  case ToleranceCheck::Kind::Max: {
    const double value = maxAbsDifference(rendered, reference);
    return {value, value <= check.limit};
  }
  case ToleranceCheck::Kind::Psnr: {
    const double value = psnr(rendered, reference);
    return {value, value >= check.limit};
  }
  case ToleranceCheck::Kind::Fraction: {
    const double value =
        fractionDiffering(rendered, reference, check.pixelThreshold);
    return {value, value <= check.limit};
  }
  }
  return {0.0, false};
}

std::string describe(const Image &image)
{
  return std::to_string(image.width) + " x " + std::to_string(image.height);
}

} // namespace

void RenderTest::SetUp()
{
  m_library = anariLoadLibrary("prism", StatusRecorder::callback, &m_status);
  ASSERT_NE(m_library, nullptr) << "cannot load the prism library";
  m_device = anariNewDevice(m_library, "default");
  ASSERT_NE(m_device, nullptr);
}

void RenderTest::TearDown()
{
  if (m_device) {
    for (ANARIObject object : m_objects)
      anariRelease(m_device, object);
    m_objects.clear();
    expectNoDeviceProblems("releasing the scene");
    anariRelease(m_device, m_device);
  }
  if (m_library)
    anariUnloadLibrary(m_library);
}

void RenderTest::expectNoDeviceProblems(const char *when)
{
  for (const StatusMessage &m : m_status.take()) {
    if (m.severity <= ANARI_SEVERITY_WARNING)
      ADD_FAILURE() << "device reported while " << when << " [severity "
                    << m.severity << ", code " << m.code << "]: " << m.text;
  }
}

ANARIWorld RenderTest::newWorld()
{
  ANARIWorld world = keep(anariNewWorld(m_device));
  anariCommitParameters(m_device, world);
  return world;
}

ANARIRenderer RenderTest::newRenderer(const std::string &subtype)
{
  std::string name = subtype;
  if (name.empty()) {
    name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    name[0] = char(std::tolower((unsigned char)name[0]));
  }
  ANARIRenderer renderer = keep(anariNewRenderer(m_device, name.c_str()));
  anariCommitParameters(m_device, renderer);
  return renderer;
}

ANARICamera RenderTest::newPerspectiveCamera(
    const std::array<float, 3> &position,
    const std::array<float, 3> &direction,
    const std::array<float, 3> &up,
    float aspect,
    float fovy)
{
  ANARICamera camera = keep(anariNewCamera(m_device, "perspective"));
  anariSetParameter(
      m_device, camera, "position", ANARI_FLOAT32_VEC3, position.data());
  anariSetParameter(
      m_device, camera, "direction", ANARI_FLOAT32_VEC3, direction.data());
  anariSetParameter(m_device, camera, "up", ANARI_FLOAT32_VEC3, up.data());
  anariSetParameter(m_device, camera, "aspect", ANARI_FLOAT32, &aspect);
  anariSetParameter(m_device, camera, "fovy", ANARI_FLOAT32, &fovy);
  anariCommitParameters(m_device, camera);
  return camera;
}

ANARIArray1D RenderTest::newArray1D(
    ANARIDataType type, const void *data, uint64_t count)
{
  ANARIArray1D array =
      keep(anariNewArray1D(m_device, nullptr, nullptr, nullptr, type, count));
  if (void *memory = anariMapArray(m_device, array)) {
    std::memcpy(memory, data, anari::sizeOf(type) * count);
    anariUnmapArray(m_device, array);
  }
  return array;
}

ANARIArray2D RenderTest::newArray2D(
    ANARIDataType type, const void *data, uint64_t width, uint64_t height)
{
  ANARIArray2D array = keep(anariNewArray2D(
      m_device, nullptr, nullptr, nullptr, type, width, height));
  if (void *memory = anariMapArray(m_device, array)) {
    std::memcpy(memory, data, anari::sizeOf(type) * width * height);
    anariUnmapArray(m_device, array);
  }
  return array;
}

Image RenderTest::render(ANARIWorld world,
    ANARICamera camera,
    ANARIRenderer renderer,
    uint32_t width,
    uint32_t height,
    uint32_t accumulatedFrames)
{
  ANARIFrame frame = anariNewFrame(m_device);
  const uint32_t size[2] = {width, height};
  const ANARIDataType colorType = ANARI_FLOAT32_VEC4;
  anariSetParameter(m_device, frame, "world", ANARI_WORLD, &world);
  anariSetParameter(m_device, frame, "camera", ANARI_CAMERA, &camera);
  anariSetParameter(m_device, frame, "renderer", ANARI_RENDERER, &renderer);
  anariSetParameter(m_device, frame, "size", ANARI_UINT32_VEC2, size);
  anariSetParameter(
      m_device, frame, "channel.color", ANARI_DATA_TYPE, &colorType);
  if (accumulatedFrames > 1) {
    const uint8_t accumulate = 1;
    anariSetParameter(m_device, frame, "accumulation", ANARI_BOOL, &accumulate);
  }
  anariCommitParameters(m_device, frame);
  for (uint32_t i = 0; i < std::max(accumulatedFrames, 1u); i++) {
    anariRenderFrame(m_device, frame);
    anariFrameReady(m_device, frame, ANARI_WAIT);
  }

  Image image;
  uint32_t mappedWidth = 0, mappedHeight = 0;
  ANARIDataType mappedType = ANARI_UNKNOWN;
  const void *pixels = anariMapFrame(m_device,
      frame,
      "channel.color",
      &mappedWidth,
      &mappedHeight,
      &mappedType);
  if (!pixels || mappedType != ANARI_FLOAT32_VEC4 || mappedWidth != width
      || mappedHeight != height) {
    ADD_FAILURE() << "channel.color mapped as " << (pixels ? "" : "NULL, ")
                  << mappedWidth << " x " << mappedHeight << " of type "
                  << anari::toString(mappedType) << "; expected " << width
                  << " x " << height << " FLOAT32_VEC4";
  } else {
    image = Image(width, height);
    std::memcpy(
        image.pixels.data(), pixels, image.pixels.size() * sizeof(Rgba));
  }
  if (pixels)
    anariUnmapFrame(m_device, frame, "channel.color");
  anariRelease(m_device, frame);
  expectNoDeviceProblems("rendering");
  return image;
}

bool RenderTest::renderAndCompare(ANARIWorld world,
    ANARICamera camera,
    ANARIRenderer renderer,
    uint32_t width,
    uint32_t height,
    const std::string &name,
    uint32_t accumulatedFrames)
{
  const auto *test = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string imageName =
      name.empty() ? std::string(test->test_suite_name()) + "." + test->name()
                   : name;
  if (width == 0 || height == 0 || width > kMaxSize || height > kMaxSize) {
    ADD_FAILURE() << imageName << ": render tests use images of at most "
                  << kMaxSize << " x " << kMaxSize << ", not " << width << " x "
                  << height;
    return false;
  }
  const Image rendered =
      render(world, camera, renderer, width, height, accumulatedFrames);
  if (rendered.empty())
    return false;
  // References are 8-bit sRGB: quantize the render the same way, so an
  // unchanged render compares exactly equal and tolerances measure only
  // rendering differences.
  const Image quantized = quantizeToSrgb8(rendered);
  const std::string referencePath =
      std::string(PRISM_RENDER_REFERENCE_DIR) + "/" + imageName + ".png";

  if (updatingReferences()) {
    ReadResult old = read(referencePath);
    if (old.ok() && old.image.width == width && old.image.height == height
        && old.image.pixels == quantized.pixels) {
      std::printf("[ REFERENCE] %s unchanged\n", referencePath.c_str());
      return true;
    }
    Status status = write(referencePath, rendered);
    if (!status.ok()) {
      ADD_FAILURE() << status.error;
      return false;
    }
    std::printf("[ REFERENCE] %s written\n", referencePath.c_str());
    return true;
  }

  const fs::path outputs = outputDirectory();
  const std::string outputBase = (outputs / imageName).string();
  // Writes what there is to look at; returns the lines naming it.
  auto writeOutputs = [&](const Image *reference) {
    std::error_code ignored;
    fs::create_directories(outputs, ignored);
    std::vector<std::pair<std::string, Image>> images;
    images.emplace_back(".rendered.png", rendered);
    if (reference) {
      images.emplace_back(".reference.png", *reference);
      if (reference->width == width && reference->height == height)
        images.emplace_back(".diff.png", diffImage(quantized, *reference));
    }
    std::string lines;
    for (const auto &[suffix, image] : images) {
      Status status = write(outputBase + suffix, image);
      lines += "\n  "
               + (status.ok() ? "wrote " + outputBase + suffix : status.error);
    }
    return lines;
  };

  ReadResult reference = read(referencePath);
  if (!reference.ok()) {
    ADD_FAILURE() << imageName << ": no usable reference image ("
                  << reference.error
                  << ")\n  if the scene is new, create it with "
                     "PRISM_UPDATE_REFERENCES=1 ctest -R 'render::"
                  << imageName << "', look at it, and commit it"
                  << writeOutputs(nullptr);
    return false;
  }
  if (reference.image.width != width || reference.image.height != height) {
    ADD_FAILURE() << imageName << ": rendered " << describe(quantized)
                  << " but the reference is " << describe(reference.image)
                  << writeOutputs(&reference.image);
    return false;
  }

  const ToleranceTable &table = tolerances();
  if (!table.error.empty()) {
    ADD_FAILURE() << table.error;
    return false;
  }
  const Comparison metrics = compare(quantized, reference.image, 1.0 / 255.0);
  ::testing::Test::RecordProperty("rmse", std::to_string(metrics.rmse));
  std::ostringstream report;
  report << imageName << " against " << referencePath << "\n  rmse "
         << metrics.rmse << " (" << metrics.rmse * 255.0 << "/255), max "
         << metrics.maxAbsDifference << ", psnr " << metrics.psnr
         << " dB, fraction>1/255 " << metrics.fractionDiffering;
  bool within = true;
  for (const ToleranceCheck &check : table.checksFor(imageName)) {
    const auto [value, passed] = evaluate(check, quantized, reference.image);
    report << "\n  " << (passed ? "ok  " : "FAIL") << " " << check.metric
           << " = " << value
           << (check.kind == ToleranceCheck::Kind::Psnr
                      ? (passed ? " >= " : " < ")
                      : (passed ? " <= " : " > "))
           << check.limit << "  (tolerances.txt:" << check.line << ", "
           << check.reason << ")";
    within = within && passed;
  }
  if (!within) {
    ADD_FAILURE() << report.str() << writeOutputs(&reference.image);
    return false;
  }
  return true;
}

uint64_t RenderTest::elementSize(ANARIDataType type)
{
  return anari::sizeOf(type);
}

ANARIArray3D RenderTest::newArray3D(ANARIDataType type,
    const void *data,
    uint64_t width,
    uint64_t height,
    uint64_t depth)
{
  ANARIArray3D array = keep(anariNewArray3D(
      m_device, nullptr, nullptr, nullptr, type, width, height, depth));
  if (void *memory = anariMapArray(m_device, array)) {
    std::memcpy(memory, data, anari::sizeOf(type) * width * height * depth);
    anariUnmapArray(m_device, array);
  }
  return array;
}

ANARIGeometry RenderTest::newGeometry(const char *subtype)
{
  return keep(anariNewGeometry(m_device, subtype));
}

ANARISampler RenderTest::newSampler(const char *subtype)
{
  return keep(anariNewSampler(m_device, subtype));
}

ANARIMaterial RenderTest::newMatte(const Vec3 &color)
{
  ANARIMaterial material = keep(anariNewMaterial(m_device, "matte"));
  setVec3(material, "color", color);
  anariCommitParameters(m_device, material);
  return material;
}

ANARIMaterial RenderTest::newMatte(const char *colorAttribute)
{
  ANARIMaterial material = keep(anariNewMaterial(m_device, "matte"));
  setString(material, "color", colorAttribute);
  anariCommitParameters(m_device, material);
  return material;
}

ANARISurface RenderTest::newSurface(
    ANARIGeometry geometry, ANARIMaterial material, uint32_t id)
{
  anariCommitParameters(m_device, geometry);
  ANARISurface surface = keep(anariNewSurface(m_device));
  setObject(surface, "geometry", ANARI_GEOMETRY, geometry);
  setObject(surface, "material", ANARI_MATERIAL, material);
  if (id != ~0u)
    setUint32(surface, "id", id);
  anariCommitParameters(m_device, surface);
  return surface;
}

ANARIGroup RenderTest::newGroup(const std::vector<ANARISurface> &surfaces)
{
  ANARIGroup group = keep(anariNewGroup(m_device));
  setObject(group,
      "surface",
      ANARI_ARRAY1D,
      newArray1D(ANARI_SURFACE, surfaces.data(), surfaces.size()));
  anariCommitParameters(m_device, group);
  return group;
}

ANARIInstance RenderTest::newInstance(ANARIGroup group)
{
  ANARIInstance instance = keep(anariNewInstance(m_device, "transform"));
  setObject(instance, "group", ANARI_GROUP, group);
  return instance;
}

ANARIWorld RenderTest::newWorld(const std::vector<ANARISurface> &surfaces,
    const std::vector<ANARIInstance> &instances)
{
  ANARIWorld world = keep(anariNewWorld(m_device));
  if (!surfaces.empty()) {
    setObject(world,
        "surface",
        ANARI_ARRAY1D,
        newArray1D(ANARI_SURFACE, surfaces.data(), surfaces.size()));
  }
  if (!instances.empty()) {
    setObject(world,
        "instance",
        ANARI_ARRAY1D,
        newArray1D(ANARI_INSTANCE, instances.data(), instances.size()));
  }
  anariCommitParameters(m_device, world);
  return world;
}

ANARICamera RenderTest::newOrthographicCamera(const Vec3 &position,
    const Vec3 &direction,
    const Vec3 &up,
    float height,
    float aspect)
{
  ANARICamera camera = keep(anariNewCamera(m_device, "orthographic"));
  setVec3(camera, "position", position);
  setVec3(camera, "direction", direction);
  setVec3(camera, "up", up);
  setFloat(camera, "height", height);
  setFloat(camera, "aspect", aspect);
  anariCommitParameters(m_device, camera);
  return camera;
}

void RenderTest::setFloat(ANARIObject object, const char *name, float value)
{
  anariSetParameter(m_device, object, name, ANARI_FLOAT32, &value);
}

void RenderTest::setUint32(ANARIObject object, const char *name, uint32_t value)
{
  anariSetParameter(m_device, object, name, ANARI_UINT32, &value);
}

void RenderTest::setVec2(
    ANARIObject object, const char *name, const Vec2 &value)
{
  anariSetParameter(m_device, object, name, ANARI_FLOAT32_VEC2, value.data());
}

void RenderTest::setVec3(
    ANARIObject object, const char *name, const Vec3 &value)
{
  anariSetParameter(m_device, object, name, ANARI_FLOAT32_VEC3, value.data());
}

void RenderTest::setVec4(
    ANARIObject object, const char *name, const Vec4 &value)
{
  anariSetParameter(m_device, object, name, ANARI_FLOAT32_VEC4, value.data());
}

void RenderTest::setMat4(
    ANARIObject object, const char *name, const Mat4 &value)
{
  anariSetParameter(m_device, object, name, ANARI_FLOAT32_MAT4, value.data());
}

void RenderTest::setString(
    ANARIObject object, const char *name, const char *value)
{
  anariSetParameter(m_device, object, name, ANARI_STRING, value);
}

void RenderTest::setObject(
    ANARIObject object, const char *name, ANARIDataType type, ANARIObject value)
{
  anariSetParameter(m_device, object, name, type, &value);
}

Mat4 translation(const Vec3 &offset)
{
  return {
      1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, offset[0], offset[1], offset[2], 1};
}

Mat4 scaling(const Vec3 &factors)
{
  return {factors[0],
      0,
      0,
      0,
      0,
      factors[1],
      0,
      0,
      0,
      0,
      factors[2],
      0,
      0,
      0,
      0,
      1};
}

Mat4 rotationZ(float radians)
{
  const float c = std::cos(radians), s = std::sin(radians);
  return {c, s, 0, 0, -s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
}

Mat4 operator*(const Mat4 &a, const Mat4 &b)
{
  Mat4 out{};
  for (int column = 0; column < 4; column++) {
    for (int row = 0; row < 4; row++) {
      float sum = 0.f;
      for (int k = 0; k < 4; k++)
        sum += a[4 * k + row] * b[4 * column + k];
      out[4 * column + row] = sum;
    }
  }
  return out;
}

void RenderTest::expectSameImage(
    const Image &a, const Image &b, const std::string &what)
{
  ASSERT_EQ(a.width, b.width) << what;
  ASSERT_EQ(a.height, b.height) << what;
  const double difference = rmse(quantizeToSrgb8(a), quantizeToSrgb8(b));
  // The default tolerance: two renders of one picture agree like a render
  // and its reference.
  EXPECT_LE(difference, 0.002) << what << ": rmse " << difference;
}

Image crop(
    const Image &image, uint32_t x, uint32_t y, uint32_t width, uint32_t height)
{
  Image out(width, height);
  for (uint32_t row = 0; row < height; row++) {
    for (uint32_t column = 0; column < width; column++)
      out.at(column, row) = image.at(x + column, y + row);
  }
  return out;
}

Image mirrorHorizontally(const Image &image)
{
  Image out(image.width, image.height);
  for (uint32_t row = 0; row < image.height; row++) {
    for (uint32_t column = 0; column < image.width; column++)
      out.at(column, row) = image.at(image.width - 1 - column, row);
  }
  return out;
}
