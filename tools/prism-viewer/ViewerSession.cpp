#include "ViewerSession.h"

#include "Environment.h"
#include "ImageIO.h"
#include "Math.h"
#include "Objects.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <numbers>

namespace prism::viewer {

using scenes::operator-;
using scenes::operator+;
using scenes::operator*;

namespace {

constexpr float kRadians = std::numbers::pi_v<float> / 180.f;

// The renderers that ignore lights by design (prism's docs/renderers.md):
// no environment is added for them.
bool ignoresLights(const std::string &renderer)
{
  return renderer == "raycast" || renderer == "ao" || renderer == "debug";
}

bool isExrPath(const std::string &path)
{
  if (path.size() < 4)
    return false;
  std::string extension = path.substr(path.size() - 4);
  for (char &c : extension)
    c = char(std::tolower((unsigned char)c));
  return extension == ".exr";
}

bool oneFloat(const std::vector<std::string> &words, float &value)
{
  if (words.size() != 1)
    return false;
  char *end = nullptr;
  value = std::strtof(words[0].c_str(), &end);
  return end && *end == '\0' && std::isfinite(value);
}

} // namespace

bool isPoseParameter(const std::string &name)
{
  for (const char *owned : {"position",
           "direction",
           "up",
           "aspect",
           "fovy",
           "height",
           "apertureRadius",
           "focusDistance"})
    if (name == owned)
      return true;
  return false;
}

void printMessage(const std::string &line)
{
  static std::mutex lock;
  std::lock_guard hold(lock);
  std::fprintf(stderr, "prism-viewer: %s\n", line.c_str());
}

ViewerSession::ViewerSession(const ViewerOptions &options)
    : m_options(options), m_session(options.verbose, &printMessage)
{}

ViewerSession::~ViewerSession()
{
  ANARIDevice device = m_session.device();
  if (!device)
    return;
  if (m_pipeline)
    m_pipeline->finish();
  m_pipeline.reset();
  releaseScene();
  for (ANARIObject o : {(ANARIObject)m_frame,
           (ANARIObject)m_renderer,
           (ANARIObject)m_cameraObject,
           (ANARIObject)m_emptyWorld})
    if (o)
      anariRelease(device, o);
}

std::string ViewerSession::open()
{
  if (!m_options.traceFile.empty()) {
    // libanari loads the validation layer around the library, recording
    // every call (as prism-render's --trace).
    setenv("ANARI_DEBUG_LAYER", "1", 1);
    setenv("ANARI_DEBUG_TRACE", m_options.traceFile.c_str(), 1);
  }
  bool usage = false;
  std::string error = m_session.open(
      {m_options.library, m_options.deviceSubtype, m_options.threads}, usage);
  if (!error.empty())
    return error;
  ANARIDevice device = m_session.device();
  m_cameraObject = anariNewCamera(device, "perspective");
  m_cameraParameters =
      ParameterSet(device, m_cameraObject, ANARI_CAMERA, "perspective");
  m_emptyWorld = anariNewWorld(device);
  anariCommitParameters(device, m_emptyWorld);
  m_frame = anariNewFrame(device);
  scenes::setObject(device, m_frame, "world", ANARI_WORLD, m_emptyWorld);
  scenes::setObject(device, m_frame, "camera", ANARI_CAMERA, m_cameraObject);
  error = setRenderer(m_options.renderer);
  if (!error.empty())
    return error;
  m_pipeline = std::make_unique<FramePipeline>(device, m_frame, m_renderer);
  m_pipeline->setSampleLimit(m_options.sampleLimit);
  anariCommitParameters(device, m_frame);
  frameScene();
  return {};
}

std::vector<std::string> ViewerSession::rendererSubtypes() const
{
  std::vector<std::string> names;
  for (const char **s = anariGetObjectSubtypes(device(), ANARI_RENDERER);
       s && *s;
       ++s)
    names.push_back(*s);
  return names;
}

std::string ViewerSession::setRenderer(const std::string &subtype)
{
  ANARIDevice device = m_session.device();
  const std::vector<std::string> known = rendererSubtypes();
  if (subtype != "default" && !known.empty()
      && std::find(known.begin(), known.end(), subtype) == known.end()) {
    std::string list;
    for (const std::string &k : known)
      list += (list.empty() ? "" : ", ") + k;
    return "the device has no renderer '" + subtype + "' (renderers: " + list
           + ")";
  }
  const MirrorScope scope = mirrored("renderer " + subtype);
  ANARIRenderer renderer = anariNewRenderer(device, subtype.c_str());
  if (m_scene.hasBackground)
    anariSetParameter(device,
        renderer,
        "background",
        ANARI_FLOAT32_VEC4,
        m_scene.background.data());
  anariCommitParameters(device, renderer);
  if (m_pipeline)
    m_pipeline->finish();
  scenes::setObject(device, m_frame, "renderer", ANARI_RENDERER, renderer);
  anariCommitParameters(device, m_frame);
  if (m_renderer)
    anariRelease(device, m_renderer);
  m_renderer = renderer;
  m_rendererSubtype = subtype;
  m_rendererParameters =
      ParameterSet(device, renderer, ANARI_RENDERER, subtype);
  observeParameters();
  if (m_pipeline) {
    m_pipeline->setRenderer(renderer);
    m_pipeline->restart();
  }
  return {};
}

void ViewerSession::releaseScene()
{
  m_lights.clear();
  m_environment = nullptr;
  m_selection.reset();
  m_selectedSurface.reset();
  if (m_scene.world)
    scenes::releaseScene(m_session.device(), m_scene);
  m_scene = {};
}

std::string ViewerSession::loadScene(const std::string &text)
{
  const MirrorScope scope = mirrored("load " + text);
  const scene_io::SourceResult source = scene_io::identifySceneSource(text);
  if (!source.ok())
    return source.error;
  scene_io::LoadOptions options;
  options.gltfCamera = m_options.cameraIndex;
  const std::string error = load(source.source, options, true);
  if (error.empty())
    m_sceneName = text;
  return error;
}

bool ViewerSession::hasFileCameras() const
{
  return m_scene.world && m_source.format == scene_io::SceneFormat::Gltf;
}

std::string ViewerSession::viewFileCamera(int index)
{
  const MirrorScope scope = mirrored("filecam " + std::to_string(index));
  if (!hasFileCameras())
    return "only glTF files have cameras to view through";
  scene_io::LoadOptions options = m_loadOptions;
  options.gltfCamera = index;
  return load(m_source, options, true);
}

bool ViewerSession::hasVolume() const
{
  return m_scene.world && scene_io::hasVolumeStyle(m_source);
}

std::string ViewerSession::restyleVolume(const TransferFunctionEdit &edit)
{
  if (m_mirror)
    return "the transfer function is not shared with the other MPI "
           "processes yet";
  if (!hasVolume())
    return "the scene has no volume whose transfer function can be edited";
  scene_io::LoadOptions options = m_loadOptions;
  if (std::string error =
          transferFunctionOptions(edit, options.transferFunction);
      !error.empty())
    return error;
  return load(m_source, options, false);
}

std::string ViewerSession::load(const scene_io::SceneSource &source,
    const scene_io::LoadOptions &options,
    bool reframe)
{
  ANARIDevice device = m_session.device();
  const int errorsBefore = m_session.errors();
  scene_io::LoadResult loaded = scene_io::loadScene(device, source, options);
  for (const std::string &note : loaded.scene.notes)
    printMessage("warning: " + note);
  if (loaded.ok() && m_session.errors() > errorsBefore)
    loaded.error =
        "the device refused the scene '" + source.name + "' (see above)";
  if (!loaded.ok()) {
    scenes::releaseScene(device, loaded.scene); // a partial one too
    return loaded.error;
  }
  m_pipeline->finish();
  releaseScene();
  m_scene = loaded.scene;
  m_source = source;
  m_loadOptions = options;
  lightScene();
  scenes::setObject(device, m_frame, "world", ANARI_WORLD, m_scene.world);
  anariCommitParameters(device, m_frame);
  if (reframe)
    frameScene();
  else
    m_pipeline->restart();
  return {};
}

void ViewerSession::lightScene()
{
  ANARIDevice device = m_session.device();
  const scene_io::Lighting lighting =
      scene_io::lightingFor(m_scene, scene_io::EnvironmentChoice{});
  if (lighting.add && !ignoresLights(m_rendererSubtype)
      && scenes::hasSubtype(device, ANARI_LIGHT, "hdri")) {
    const scenes::Vec3 up =
        m_scene.camera.valid ? m_scene.camera.up : scenes::Vec3{0.f, 1.f, 0.f};
    const scene_io::Environment environment =
        scene_io::makeEnvironment(device, lighting.environment, up);
    if (environment.error.empty()) {
      scene_io::addWorldLight(device, m_scene, environment.light);
      m_environment = environment.light;
    } else {
      printMessage("warning: " + environment.error);
    }
  }
  describeLights();
}

// The environment the viewer added first (light 0 when there is one), then
// the scene's own lights whose subtypes the scene lists.
void ViewerSession::describeLights()
{
  m_lights.clear();
  if (m_environment)
    m_lights.push_back({"environment (hdri)",
        ParameterSet(device(), m_environment, ANARI_LIGHT, "hdri")});
  for (ANARILight light : m_scene.lights) {
    const std::string subtype = scenes::lightSubtype(m_scene, light);
    if (light == m_environment || subtype.empty())
      continue;
    m_lights.push_back(
        {"light " + std::to_string(m_lights.size()) + " (" + subtype + ")",
            ParameterSet(device(), light, ANARI_LIGHT, subtype)});
  }
  observeParameters();
}

void ViewerSession::selectSurface()
{
  m_selectedSurface.reset();
  if (!m_selection || m_selection->objectId == kNoId)
    return;
  for (const scenes::SceneSurface &s : m_scene.surfaces) {
    if (s.id != m_selection->objectId)
      continue;
    m_selectedSurface = SelectedSurface{"surface " + std::to_string(s.id) + ": "
                                            + s.geometrySubtype + " geometry, "
                                            + s.materialSubtype + " material",
        ParameterSet(device(), s.material, ANARI_MATERIAL, s.materialSubtype),
        ParameterSet(device(), s.geometry, ANARI_GEOMETRY, s.geometrySubtype)};
    return;
  }
}

scenes::Bounds ViewerSession::worldBounds() const
{
  scenes::Bounds bounds;
  float box[6] = {};
  if (m_scene.world
      && anariGetProperty(device(),
          m_scene.world,
          "bounds",
          ANARI_FLOAT32_BOX3,
          box,
          sizeof(box),
          ANARI_WAIT)
      && std::all_of(box, box + 6, [](float v) { return std::isfinite(v); })) {
    bounds.extend(scenes::Vec3{box[0], box[1], box[2]});
    bounds.extend(scenes::Vec3{box[3], box[4], box[5]});
  }
  return bounds.empty() ? m_scene.bounds : bounds;
}

void ViewerSession::frameScene()
{
  const MirrorScope scope = mirrored("frame");
  const scenes::Bounds bounds = worldBounds();
  const float aspect = m_width > 0 && m_height > 0
                           ? float(m_width) / float(m_height)
                           : 4.f / 3.f;
  const scene_io::CameraSetup setup = scene_io::frameCamera(
      m_scene.camera, bounds, aspect, {}, m_scene.outline);
  const Vec3 centre =
      bounds.empty() ? setup.at : (bounds.lower + bounds.upper) * 0.5f;
  m_camera.reset(setup, centre);
  cameraChanged();
}

void ViewerSession::useCameraSubtype(const std::string &subtype)
{
  if (m_cameraParameters.subtype() == subtype)
    return;
  ANARIDevice device = m_session.device();
  if (m_pipeline)
    m_pipeline->finish();
  ANARICamera camera = anariNewCamera(device, subtype.c_str());
  scenes::setObject(device, m_frame, "camera", ANARI_CAMERA, camera);
  anariCommitParameters(device, m_frame);
  anariRelease(device, m_cameraObject);
  m_cameraObject = camera;
  m_cameraParameters = ParameterSet(device, camera, ANARI_CAMERA, subtype);
  observeParameters();
}

void ViewerSession::cameraChanged()
{
  const MirrorScope scope = mirrored(poseLine(m_camera.pose()));
  ANARIDevice device = m_session.device();
  const CameraPose &pose = m_camera.pose();
  // A file's orthographic camera is viewed as one (the pose keeps its
  // height, which zooming scales).
  useCameraSubtype(pose.orthographic ? "orthographic" : "perspective");
  const float aspect = m_width > 0 && m_height > 0
                           ? float(m_width) / float(m_height)
                           : 4.f / 3.f;
  scenes::setVec3(device, m_cameraObject, "position", pose.eye);
  scenes::setVec3(device,
      m_cameraObject,
      "direction",
      scenes::normalize(pose.at - pose.eye));
  scenes::setVec3(device, m_cameraObject, "up", pose.up);
  scenes::setFloat(device, m_cameraObject, "aspect", aspect);
  if (pose.orthographic) {
    scenes::setFloat(device, m_cameraObject, "height", pose.height);
  } else {
    scenes::setFloat(
        device, m_cameraObject, "fovy", pose.fovyDegrees * kRadians);
  }
  if (!pose.orthographic
      && (pose.apertureRadius > 0.f
          || m_cameraParameters.find("apertureRadius"))) {
    scenes::setFloat(
        device, m_cameraObject, "apertureRadius", pose.apertureRadius);
    scenes::setFloat(
        device, m_cameraObject, "focusDistance", pose.focusDistance);
  }
  anariCommitParameters(device, m_cameraObject);
  if (m_pipeline)
    m_pipeline->restart();
}

void ViewerSession::setViewport(uint32_t width, uint32_t height, float scale)
{
  if (width == 0 || height == 0 || !m_pipeline)
    return;
  const bool resized = width != m_width || height != m_height;
  if (!resized && scale == m_scale)
    return;
  const MirrorScope scope = mirrored(viewportLine(width, height, scale));
  m_width = width;
  m_height = height;
  m_scale = scale;
  const auto scaled = [&](uint32_t v) {
    return std::max(1u, uint32_t(std::lround(float(v) * scale)));
  };
  m_pipeline->setSize(scaled(width), scaled(height));
  if (resized)
    cameraChanged();
}

bool ViewerSession::update()
{
  return m_pipeline && m_pipeline->poll();
}

std::string ViewerSession::setParameter(const std::string &target,
    int index,
    const std::string &name,
    const std::vector<std::string> &words)
{
  ParameterSet *set = nullptr;
  if (target == "renderer" || target == "camera") {
    if (index != 0)
      return "there is one " + target + " (index 0), not "
             + std::to_string(index);
    set = target == "renderer" ? &m_rendererParameters : &m_cameraParameters;
  } else if (target == "material" || target == "geometry") {
    if (m_mirror)
      return "the picked surface's " + target
             + " is not shared with the other MPI processes yet";
    if (!m_selectedSurface)
      return "pick a surface the scene lists first (nothing picked, or the "
             "scene does not list the picked surface)";
    set = target == "material" ? &m_selectedSurface->material
                               : &m_selectedSurface->geometry;
  } else if (target == "light") {
    if (index < 0 || size_t(index) >= m_lights.size())
      return "there is no light " + std::to_string(index) + " ("
             + std::to_string(m_lights.size()) + " light"
             + (m_lights.size() == 1 ? "" : "s") + " with known subtypes)";
    set = &m_lights[index].parameters;
  } else {
    return "set applies to renderer, camera, light, material or geometry";
  }
  if (target == "camera" && isPoseParameter(name)) {
    // The pose owns these: it would overwrite them on the next move.
    float v = 0.f;
    if (name == "fovy" || name == "apertureRadius" || name == "focusDistance") {
      if (!oneFloat(words, v))
        return "'" + name + "' takes one number";
      if (name == "fovy")
        m_camera.setFovy(v / kRadians);
      else if (name == "apertureRadius")
        m_camera.setAperture(v);
      else
        m_camera.focusOn(
            m_camera.pose().eye
            + scenes::normalize(m_camera.pose().at - m_camera.pose().eye) * v);
      cameraChanged();
      return {};
    }
    return "the camera's '" + name
           + "' follows the viewer's moves (orbit, pan, zoom, fly) and the "
             "window";
  }
  const std::string error = set->setFromWords(name, words);
  if (error.empty())
    parametersChanged();
  return error;
}

void ViewerSession::parametersChanged()
{
  if (m_pipeline)
    m_pipeline->restart();
}

std::optional<Pick> ViewerSession::pick(int x, int y)
{
  std::optional<Pick> picked =
      pickAt(m_pipeline->ids(), x, y, m_width, m_height);
  m_selection = picked && picked->hit ? picked : std::nullopt;
  selectSurface();
  return picked;
}

bool ViewerSession::focusAt(int x, int y)
{
  const std::optional<Pick> p =
      pickAt(m_pipeline->ids(), x, y, m_width, m_height);
  if (!p || !p->depth)
    return false;
  // Depth is the distance along the pixel's ray; the focus distance is
  // along the view direction, close enough for a focus click.
  m_camera.focusOn(m_camera.pose().eye
                   + scenes::normalize(m_camera.pose().at - m_camera.pose().eye)
                         * *p->depth);
  cameraChanged();
  return true;
}

Rgba8Image ViewerSession::shownImage() const
{
  Rgba8Image image = m_pipeline->image();
  const FrameIds &ids = m_pipeline->ids();
  if (m_selection && ids.width == image.width && ids.height == image.height)
    tint(image, pickedMask(ids, *m_selection));
  return image;
}

std::string ViewerSession::screenshot(const std::string &path) const
{
  const Rgba8Image &shown = m_pipeline->image();
  if (shown.pixels.empty())
    return std::string("the device gives no ")
           + channelName(m_pipeline->imageChannel()) + " channel to save";
  image::Image out(shown.width, shown.height);
  const LinearColorImage &linear = m_pipeline->linearColor();
  if (isExrPath(path) && linear.width == shown.width
      && linear.height == shown.height && !linear.pixels.empty()) {
    // HDR: the device's floats as they are, values above 1 included.
    for (size_t i = 0; i < out.pixels.size(); ++i)
      for (int c = 0; c < 4; ++c)
        out.pixels[i][c] = linear.pixels[4 * i + c];
  } else {
    for (size_t i = 0; i < out.pixels.size(); ++i)
      for (int c = 0; c < 4; ++c) {
        const float v = shown.pixels[4 * i + c] / 255.f;
        out.pixels[i][c] = c == 3 ? v : image::linearFromSrgb(v);
      }
  }
  const image::Status written = image::write(path, out);
  return written.ok() ? std::string() : written.error;
}

} // namespace prism::viewer
