// libFuzzer target for prism-render's scene loaders. The first byte picks
// the format (its value mod 5), the rest is the file, loaded from memory
// into one `prism` device made once per process:
//   0  glTF JSON       loadGltfFromMemory (external URIs not read)
//   1  GLB             the same (the magic decides)
//   2  OBJ             loadObj, no material library
//   3  OBJ + MTL       loadObj; the text after the first NUL byte is the MTL
//                      every `mtllib` gets
//   4  NanoVDB         loadNanoVdb, through a temporary file (NanoVDB's
//                      reader reads files)
// Textures named by an MTL are never opened. A loaded world is committed,
// framed by prism-render's camera framing and rendered once at 4x4 with
// `raycast`, so what the loaders hand the device is used, not just stored.
#include "CameraFraming.h"
#include "GltfLoader.h"
#include "Math.h"
#include "NanoVdbLoader.h"
#include "ObjLoader.h"

#include <anari/anari.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace {

using namespace prism::scene_io;
using prism::scenes::operator-;

// Device messages are expected for broken inputs; crashes are what count.
void quietStatus(const void *,
    ANARIDevice,
    ANARIObject,
    ANARIDataType,
    ANARIStatusSeverity,
    ANARIStatusCode,
    const char *)
{}

struct Session
{
  ANARILibrary library{nullptr};
  ANARIDevice device{nullptr};
  ANARICamera camera{nullptr};
  ANARIRenderer renderer{nullptr};
  ANARIFrame frame{nullptr};
};

Session g_session;
// FUZZ_LOADER_VERBOSE=1: one line per input saying what came of it (for
// checking that seeds load).
bool g_verbose = false;

void setVec3(ANARIObject object, const char *name, const prism::scenes::Vec3 &v)
{
  anariSetParameter(
      g_session.device, object, name, ANARI_FLOAT32_VEC3, v.data());
}

void render(const LoadResult &loaded)
{
  ANARIDevice d = g_session.device;
  const CameraSetup camera = frameCamera(loaded.scene.camera,
      loaded.scene.bounds,
      1.f,
      CameraOverrides{},
      loaded.scene.outline);
  setVec3(g_session.camera, "position", camera.eye);
  setVec3(g_session.camera, "direction", camera.at - camera.eye);
  setVec3(g_session.camera, "up", camera.up);
  anariCommitParameters(d, g_session.camera);
  anariSetParameter(
      d, g_session.frame, "world", ANARI_WORLD, &loaded.scene.world);
  anariCommitParameters(d, g_session.frame);
  anariRenderFrame(d, g_session.frame);
  anariFrameReady(d, g_session.frame, ANARI_WAIT);
  uint32_t width = 0, height = 0;
  ANARIDataType type = ANARI_UNKNOWN;
  const void *pixels = anariMapFrame(
      d, g_session.frame, "channel.color", &width, &height, &type);
  if (pixels)
    anariUnmapFrame(d, g_session.frame, "channel.color");
  // The frame must not keep the world alive into the next input.
  anariUnsetParameter(d, g_session.frame, "world");
  anariCommitParameters(d, g_session.frame);
}

constexpr int kFormats = 5;

LoadResult loadNanoVdbBytes(const std::string &bytes)
{
  static const std::string path =
      (std::filesystem::temp_directory_path()
          / ("fuzz_loader-" + std::to_string(::getpid()) + ".nvdb"))
          .string();
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(bytes.data(), std::streamsize(bytes.size()));
  LoadResult loaded =
      loadNanoVdb(g_session.device, path, "", TransferFunctionOptions{});
  std::filesystem::remove(path);
  return loaded;
}

LoadResult load(uint8_t format, const std::string &bytes)
{
  ANARIDevice d = g_session.device;
  if (format == 4)
    return loadNanoVdbBytes(bytes);
  if (format < 2) {
    GltfOptions options;
    options.readExternalFiles = false;
    return loadGltfFromMemory(
        d, bytes, format == 0 ? "fuzz.gltf" : "fuzz.glb", options);
  }
  ObjSource source;
  source.path = "fuzz.obj";
  source.readTextures = false;
  std::string mtl;
  const size_t split = format == 3 ? bytes.find('\0') : std::string::npos;
  source.text = bytes.substr(0, split);
  if (split != std::string::npos)
    mtl = bytes.substr(split + 1);
  source.readMaterialLibrary =
      [&](const std::string &, std::string &text, std::string &error) {
        if (format != 3) {
          error = "no material libraries here";
          return false;
        }
        text = mtl;
        return true;
      };
  return loadObj(d, source);
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int *, char ***)
{
  Session &s = g_session;
  const char *verbose = std::getenv("FUZZ_LOADER_VERBOSE");
  g_verbose = verbose && *verbose && *verbose != '0';
  s.library = anariLoadLibrary("prism", quietStatus, nullptr);
  if (!s.library) {
    std::fprintf(stderr, "fuzz_loader: cannot load the prism library\n");
    std::exit(1);
  }
  s.device = anariNewDevice(s.library, "default");
  if (!s.device) {
    std::fprintf(stderr, "fuzz_loader: the prism library has no device\n");
    std::exit(1);
  }
  anariCommitParameters(s.device, s.device);
  s.camera = anariNewCamera(s.device, "perspective");
  const float aspect = 1.f;
  anariSetParameter(s.device, s.camera, "aspect", ANARI_FLOAT32, &aspect);
  anariCommitParameters(s.device, s.camera);
  s.renderer = anariNewRenderer(s.device, "raycast");
  anariCommitParameters(s.device, s.renderer);
  s.frame = anariNewFrame(s.device);
  const uint32_t size[2] = {4, 4};
  anariSetParameter(s.device, s.frame, "size", ANARI_UINT32_VEC2, size);
  const ANARIDataType color = ANARI_UFIXED8_RGBA_SRGB;
  anariSetParameter(
      s.device, s.frame, "channel.color", ANARI_DATA_TYPE, &color);
  anariSetParameter(s.device, s.frame, "camera", ANARI_CAMERA, &s.camera);
  anariSetParameter(s.device, s.frame, "renderer", ANARI_RENDERER, &s.renderer);
  anariCommitParameters(s.device, s.frame);
  // Released at exit so LeakSanitizer sees only what inputs leaked. The
  // library stays loaded: unloading it after a render unloads libtbb under
  // the device's live worker threads (a crash in the device, reported
  // separately).
  std::atexit([] {
    Session &s = g_session;
    anariRelease(s.device, s.frame);
    anariRelease(s.device, s.renderer);
    anariRelease(s.device, s.camera);
    anariRelease(s.device, s.device);
  });
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  if (size < 1)
    return 0;
  const std::string bytes((const char *)data + 1, size - 1);
  LoadResult loaded = load(data[0] % kFormats, bytes);
  if (g_verbose)
    std::fprintf(stderr,
        "fuzz_loader: format %d: %s\n",
        data[0] % kFormats,
        loaded.ok() ? "loaded and rendered" : loaded.error.c_str());
  if (loaded.scene.world)
    render(loaded);
  prism::scenes::releaseScene(g_session.device, loaded.scene);
  return 0;
}
