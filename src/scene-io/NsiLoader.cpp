#include "NsiLoader.h"

#include "Outline.h"

#include "AnariWorldBuilder.h"
#include "Context.h"
#include "ContextTable.h"
#include "PathExpansion.h"
#include "SceneResolver.h"
#include "StreamReader.h"
#include "StreamSource.h"

#include <cctype>
#include <cmath>
#include <numbers>

namespace prism::scene_io {
namespace {

bool isDelimiter(char ch)
{
  return std::isspace((unsigned char)ch) || ch == '"' || ch == '[' || ch == ']'
         || ch == '#';
}

// Collects what libnsi reports; errors fail the load.
struct Problems
{
  std::vector<std::string> errors;

  void report(int level, const std::string &message)
  {
    if (level >= NSIErrError)
      errors.push_back(message);
  }
  static void handler(void *data, int level, int, const char *message)
  {
    static_cast<Problems *>(data)->report(level, message ? message : "");
  }
};

scenes::Vec3 toVec3(const std::array<double, 3> &v)
{
  return {float(v[0]), float(v[1]), float(v[2])};
}

// Bounds and outline of the surfaces at their first placement's keys.
void outlineSurfaces(const nsi::ResolvedScene &resolved, scenes::Scene &scene)
{
  for (const nsi::SurfaceItem &item : resolved.surfaces) {
    const auto geometry = resolved.geometries.find(item.geometryHandle);
    if (geometry == resolved.geometries.end() || geometry->second.isPlane)
      continue;
    std::vector<scenes::Vec3> local;
    const std::vector<float> &positions = geometry->second.positions;
    sampleOutline(positions.data(), positions.size() / 3, local);
    for (const nsi::Placement &placement : item.worldFromObject) {
      if (placement.empty() || scene.outline.size() >= kMaxOutline)
        continue;
      for (const scenes::Vec3 &p : local) {
        const scenes::Vec3 world =
            toVec3(nsi::transformPoint(placement.front(), {p[0], p[1], p[2]}));
        scene.outline.push_back(world);
        scene.bounds.extend(world);
      }
    }
  }
}

// The first camera with a screen, as the scene's camera: looking down its
// -Z with +Y up, `at` level with the middle of the bounds.
void placeCamera(const nsi::ResolvedScene &resolved, scenes::Scene &scene)
{
  if (resolved.cameras.empty())
    return;
  const nsi::CameraItem &item = resolved.cameras.front();
  const nsi::Framing framing =
      nsi::frameCamera(item.orthographic, item.fov, item.screen);
  scenes::SuggestedCamera &camera = scene.camera;
  camera.valid = true;
  camera.eye = toVec3(nsi::transformPoint(item.worldFromCamera, {0, 0, 0}));
  const scenes::Vec3 direction =
      toVec3(nsi::transformVector(item.worldFromCamera, {0, 0, -1}));
  camera.up = toVec3(nsi::transformVector(item.worldFromCamera, {0, 1, 0}));
  float distance = 1.f;
  if (!scene.bounds.empty()) {
    float along = 0.f, length = 0.f;
    for (int i = 0; i < 3; ++i) {
      const float centre =
          0.5f * (scene.bounds.lower[i] + scene.bounds.upper[i]);
      along += (centre - camera.eye[i]) * direction[i];
      length += direction[i] * direction[i];
    }
    if (length > 0.f && along > 0.f)
      distance = along / length;
  }
  for (int i = 0; i < 3; ++i)
    camera.at[i] = camera.eye[i] + distance * direction[i];
  camera.orthographic = item.orthographic;
  camera.height = framing.height;
  if (!item.orthographic)
    camera.fovyDegrees = float(framing.fovy * 180.0 / std::numbers::pi);
}

std::string failure(const std::string &fileName, const Problems &problems)
{
  // The reader's messages begin with the file's name already.
  const std::string &first = problems.errors.front();
  std::string error = first.rfind(fileName, 0) == 0
                          ? first
                          : "NSI stream '" + fileName + "': " + first;
  if (problems.errors.size() > 1)
    error += " (and " + std::to_string(problems.errors.size() - 1)
             + " more error" + (problems.errors.size() > 2 ? "s" : "") + ")";
  return error;
}

// Builds the world of `resolved` on `device`; the scene keeps its own
// reference to the world, the builder's goes with it.
void buildWorld(ANARIDevice device,
    const nsi::ResolvedScene &resolved,
    Problems &problems,
    scenes::Scene &scene)
{
  nsi::AnariWorldBuilder builder(
      device,
      [&](int level, const std::string &message) {
        problems.report(level, message);
      },
      false);
  const nsi::AnariWorld world = builder.update(resolved);
  if (!world.world)
    return;
  anariRetain(device, world.world);
  scene.world = world.world;
  scene.hasBackground = true;
  scene.background = world.background;
  if (world.ambientRadiance > 0.f)
    scene.notes.push_back("the stream's ambient light is left out");
}

} // namespace

std::string withoutRenderControl(const std::string &text)
{
  static const std::string keyword = "RenderControl";
  std::string out = text;
  bool cutting = false;
  size_t cutFrom = 0;
  auto blank = [&](size_t end) {
    for (size_t i = cutFrom; i < end; ++i)
      if (out[i] != '\n')
        out[i] = ' ';
  };
  size_t at = 0;
  while (at < text.size()) {
    const char ch = text[at];
    if (ch == '"') { // a string, escapes and all
      for (++at; at < text.size() && text[at] != '"'; ++at)
        if (text[at] == '\\')
          ++at;
      ++at;
    } else if (ch == '#') {
      while (at < text.size() && text[at] != '\n')
        ++at;
    } else if (isDelimiter(ch)) {
      ++at;
    } else {
      size_t end = at;
      while (end < text.size() && !isDelimiter(text[end]))
        ++end;
      // Keywords are the bare words that start with a letter (numbers do
      // not): one ends the statement being cut.
      if (std::isalpha((unsigned char)ch)) {
        if (cutting)
          blank(at);
        cutting = text.compare(at, end - at, keyword) == 0;
        cutFrom = at;
      }
      at = end;
    }
  }
  if (cutting)
    blank(text.size());
  return out;
}

LoadResult loadNsi(ANARIDevice device, const std::string &fileName)
{
  LoadResult result;
  std::string text, why;
  if (!nsi::readStreamText(fileName, text, why)) {
    result.error = "cannot read NSI stream '" + fileName + "': " + why;
    return result;
  }
  Problems problems;
  NSIErrorHandler_t handler = &Problems::handler;
  void *handlerData = &problems;
  const NSIParam_t params[] = {
      {"errorhandler", &handler, NSITypePointer, 0, 1, 0},
      {"errorhandlerdata", &handlerData, NSITypePointer, 0, 1, 0}};
  const NSIContext_t context = NSIBegin(2, params);
  const std::shared_ptr<nsi::Context> graphOwner =
      nsi::ContextTable::instance().find(context);
  if (!graphOwner) {
    result.error = "NSI stream '" + fileName + "': no NSI context";
    return result;
  }
  nsi::StreamReader(
      context,
      [&](int level, const std::string &message) {
        problems.report(level, message);
      },
      fileName)
      .read(withoutRenderControl(text));
  const nsi::ResolvedScene resolved = nsi::resolveScene(
      graphOwner->graph(),
      [&](int level, const std::string &message) {
        problems.report(level, message);
      },
      nsi::expandPath);
  if (problems.errors.empty())
    buildWorld(device, resolved, problems, result.scene);
  NSIEnd(context);
  if (!problems.errors.empty()) {
    if (result.scene.world)
      anariRelease(device, result.scene.world);
    result.scene = {};
    result.error = failure(fileName, problems);
    return result;
  }
  result.scene.name = fileName;
  outlineSurfaces(resolved, result.scene);
  placeCamera(resolved, result.scene);
  return result;
}

} // namespace prism::scene_io
