#include "Options.h"

#include "ColorMaps.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <functional>

namespace prism::render {
namespace {

std::string lowerCase(std::string text)
{
  for (char &c : text)
    c = char(std::tolower((unsigned char)c));
  return text;
}

// A whole decimal number in [minimum, maximum]; no sign games, no suffixes.
bool parseUnsigned(
    const std::string &text, uint64_t minimum, uint64_t maximum, uint64_t &out)
{
  if (text.empty() || !std::isdigit((unsigned char)text[0]))
    return false;
  errno = 0;
  char *end = nullptr;
  const unsigned long long value = std::strtoull(text.c_str(), &end, 10);
  if (errno != 0 || *end != '\0' || value < minimum || value > maximum)
    return false;
  out = value;
  return true;
}

bool parseUint32(const std::string &text, uint32_t minimum, uint32_t &out)
{
  uint64_t value = 0;
  if (!parseUnsigned(text, minimum, 0xffffffffull, value))
    return false;
  out = uint32_t(value);
  return true;
}

// "WxH" or "W,H" or "WxHxD": `count` positive integers up to `maximum`.
bool parseExtent(
    const std::string &text, int count, uint64_t maximum, uint64_t *values)
{
  std::string rest = lowerCase(text);
  std::replace(rest.begin(), rest.end(), ',', 'x');
  for (int i = 0; i < count; i++) {
    const size_t separator = rest.find('x');
    const bool last = i + 1 == count;
    if (last != (separator == std::string::npos))
      return false;
    if (!parseUnsigned(rest.substr(0, separator), 1, maximum, values[i]))
      return false;
    rest = last ? std::string() : rest.substr(separator + 1);
  }
  return true;
}

// One command-line option: its spellings, whether it takes a value and
// what it does with it (returning an error message, or empty).
struct OptionSpec
{
  const char *shortName; // may be nullptr
  const char *longName;
  bool takesValue;
  std::function<std::string(Options &, const std::string &)> apply;
};

std::string expected(const std::string &option,
    const std::string &what,
    const std::string &value)
{
  return option + ": expected " + what + ", got '" + value + "'";
}

// Pixel and sample counts are capped where a typo would otherwise ask for
// terabytes (64k x 64k pixels, a million samples).
constexpr uint64_t kMaxImageSide = 65536;

// Options for the scene, the image and its samples.
std::vector<OptionSpec> inputAndImageOptions()
{
  return {
      {"-o",
          "--output",
          true,
          [](Options &o, const std::string &v) -> std::string {
            if (!isImagePath(v))
              return "--output: cannot write '" + v
                     + "': the name must end in .png, .exr or .pfm";
            o.output = v;
            return {};
          }},
      {nullptr,
          "--scene",
          true,
          [](Options &o, const std::string &v) -> std::string {
            if (!o.scene.empty())
              return "--scene: a scene was already given ('" + o.scene + "')";
            o.scene = v;
            return {};
          }},
      {nullptr,
          "--size",
          true,
          [](Options &o, const std::string &v) -> std::string {
            uint64_t extent[2];
            if (!parseExtent(v, 2, kMaxImageSide, extent))
              return expected("--size",
                  "WIDTHxHEIGHT, each from 1 to 65536 (e.g. 1024x768)",
                  v);
            o.width = uint32_t(extent[0]);
            o.height = uint32_t(extent[1]);
            return {};
          }},
      {nullptr,
          "--spp",
          true,
          [](Options &o, const std::string &v) -> std::string {
            uint64_t n = 0;
            if (!parseUnsigned(v, 1, 1000000, n))
              return expected("--spp", "a sample count from 1 to 1000000", v);
            o.samplesPerPixel = uint32_t(n);
            return {};
          }},
  };
}

// Options for the renderer and its parameters.
std::vector<OptionSpec> rendererOptions()
{
  return {
      {"-r",
          "--renderer",
          true,
          [](Options &o, const std::string &v) -> std::string {
            if (v.empty())
              return "--renderer: expected a renderer subtype";
            o.renderer = v;
            return {};
          }},
      {"-p",
          "--param",
          true,
          [](Options &o, const std::string &v) -> std::string {
            const size_t equals = v.find('=');
            if (equals == std::string::npos || equals == 0)
              return expected("--param", "NAME=VALUE", v);
            o.rendererParameters.emplace_back(
                v.substr(0, equals), v.substr(equals + 1));
            return {};
          }},
  };
}

// Options for the view, and what of a glTF file is shown.
std::vector<OptionSpec> cameraOptions()
{
  return {
      {nullptr,
          "--eye",
          true,
          [](Options &o, const std::string &v) -> std::string {
            Vec3 p;
            if (!parseFloats(v, p.data(), 3))
              return expected("--eye", "three numbers x,y,z", v);
            o.eye = p;
            return {};
          }},
      {nullptr,
          "--at",
          true,
          [](Options &o, const std::string &v) -> std::string {
            Vec3 p;
            if (!parseFloats(v, p.data(), 3))
              return expected("--at", "three numbers x,y,z", v);
            o.at = p;
            return {};
          }},
      {nullptr,
          "--up",
          true,
          [](Options &o, const std::string &v) -> std::string {
            Vec3 p;
            if (!parseFloats(v, p.data(), 3)
                || (p[0] == 0.f && p[1] == 0.f && p[2] == 0.f))
              return expected("--up", "a non-zero direction x,y,z", v);
            o.up = p;
            return {};
          }},
      {nullptr,
          "--fovy",
          true,
          [](Options &o, const std::string &v) -> std::string {
            float f = 0.f;
            if (!parseFloats(v, &f, 1) || !(f > 0.f && f < 180.f))
              return expected(
                  "--fovy", "an angle in degrees between 0 and 180", v);
            o.fovyDegrees = f;
            return {};
          }},
      {nullptr,
          "--camera",
          true,
          [](Options &o, const std::string &v) -> std::string {
            uint32_t index = 0;
            if (!parseUint32(v, 0, index) || index > 1000000)
              return expected("--camera", "a glTF camera index (0, 1, ...)", v);
            o.cameraIndex = int(index);
            return {};
          }},
      {nullptr,
          "--variant",
          true,
          [](Options &o, const std::string &v) -> std::string {
            if (v.empty())
              return expected("--variant", "a material variant's name", v);
            o.variant = v;
            return {};
          }},
      {nullptr,
          "--time",
          true,
          [](Options &o, const std::string &v) -> std::string {
            float f = 0.f;
            if (!parseFloats(v, &f, 1) || !(std::abs(f) <= 1e9f))
              return expected("--time", "a time in seconds", v);
            o.time = f;
            return {};
          }},
  };
}

// Options for the environment and the background.
std::vector<OptionSpec> lightingOptions()
{
  return {
      {nullptr,
          "--env",
          true,
          [](Options &o, const std::string &v) -> std::string {
            if (v.empty())
              return expected(
                  "--env", "studio, none or an image file (.hdr, .exr)", v);
            o.environment = v;
            o.environmentGiven = true;
            return {};
          }},
      {nullptr,
          "--env-intensity",
          true,
          [](Options &o, const std::string &v) -> std::string {
            float f = 0.f;
            if (!parseFloats(v, &f, 1) || !(f >= 0.f && f <= 1e6f))
              return expected(
                  "--env-intensity", "a scale factor from 0 to 1000000", v);
            o.environmentIntensity = f;
            return {};
          }},
      {nullptr,
          "--env-rotate",
          true,
          [](Options &o, const std::string &v) -> std::string {
            float f = 0.f;
            if (!parseFloats(v, &f, 1) || !(std::abs(f) <= 36000.f))
              return expected("--env-rotate", "an angle in degrees", v);
            o.environmentRotateDegrees = f;
            return {};
          }},
      {nullptr,
          "--background",
          true,
          [](Options &o, const std::string &v) -> std::string {
            std::array<float, 4> c{0.f, 0.f, 0.f, 1.f};
            if (!parseFloats(v, c.data(), 4) && !parseFloats(v, c.data(), 3))
              return expected("--background", "r,g,b or r,g,b,a", v);
            o.background = c;
            return {};
          }},
  };
}

// Options for the frame channels written besides color.
std::vector<OptionSpec> channelOptions()
{
  return {
      {nullptr,
          "--depth",
          true,
          [](Options &o, const std::string &v) -> std::string {
            if (!isImagePath(v))
              return "--depth: cannot write '" + v
                     + "': the name must end in .png, .exr or .pfm";
            o.depthPath = v;
            return {};
          }},
      {nullptr,
          "--normal",
          true,
          [](Options &o, const std::string &v) -> std::string {
            if (!isImagePath(v))
              return "--normal: cannot write '" + v
                     + "': the name must end in .png, .exr or .pfm";
            o.normalPath = v;
            return {};
          }},
      {nullptr,
          "--albedo",
          true,
          [](Options &o, const std::string &v) -> std::string {
            if (!isImagePath(v))
              return "--albedo: cannot write '" + v
                     + "': the name must end in .png, .exr or .pfm";
            o.albedoPath = v;
            return {};
          }},
      {nullptr,
          "--ids",
          true,
          [](Options &o, const std::string &v) -> std::string {
            if (v.empty())
              return "--ids: expected a file name prefix";
            o.idsPrefix = v;
            return {};
          }},
      {nullptr,
          "--denoise",
          false,
          [](Options &o, const std::string &) -> std::string {
            o.denoise = true;
            return {};
          }},
  };
}

// Options for the library, the device and how it runs.
std::vector<OptionSpec> deviceOptions()
{
  return {
      {nullptr,
          "--mpi-partition",
          false,
          [](Options &o, const std::string &) -> std::string {
            o.mpiPartition = true;
            return {};
          }},
      {"-l",
          "--library",
          true,
          [](Options &o, const std::string &v) -> std::string {
            if (v.empty())
              return "--library: expected an ANARI library name";
            o.library = v;
            return {};
          }},
      {nullptr,
          "--trace",
          true,
          [](Options &o, const std::string &v) -> std::string {
            if (v.empty())
              return "--trace: expected a file name";
            o.traceFile = v;
            return {};
          }},
      {"-d",
          "--device",
          true,
          [](Options &o, const std::string &v) -> std::string {
            if (v.empty())
              return "--device: expected a device subtype";
            o.deviceSubtype = v;
            return {};
          }},
      {nullptr,
          "--bench",
          true,
          [](Options &o, const std::string &v) -> std::string {
            uint64_t n = 0;
            if (!parseUnsigned(v, 1, 100000, n))
              return expected("--bench", "a frame count from 1 to 100000", v);
            o.benchFrames = uint32_t(n);
            return {};
          }},
      {"-t",
          "--threads",
          true,
          [](Options &o, const std::string &v) -> std::string {
            uint64_t n = 0;
            if (!parseUnsigned(v, 1, 4096, n))
              return expected("--threads", "a thread count from 1 to 4096", v);
            o.threads = uint32_t(n);
            return {};
          }},
  };
}

// Options for raw and NanoVDB volumes and their transfer function.
std::vector<OptionSpec> volumeOptions()
{
  return {
      {nullptr,
          "--raw-dims",
          true,
          [](Options &o, const std::string &v) -> std::string {
            std::array<uint64_t, 3> d{};
            if (!parseExtent(v, 3, 1u << 20, d.data()))
              return expected(
                  "--raw-dims", "XxYxZ voxel counts (e.g. 64x64x64)", v);
            o.rawDimensions = d;
            return {};
          }},
      {nullptr,
          "--raw-type",
          true,
          [](Options &o, const std::string &v) -> std::string {
            const std::string t = lowerCase(v);
            static const char *kTypes[] = {
                "uint8", "int16", "uint16", "float32", "float64"};
            for (const char *known : kTypes)
              if (t == known) {
                o.rawType = t;
                return {};
              }
            return expected("--raw-type",
                "one of uint8, int16, uint16, float32, float64",
                v);
          }},
      {nullptr,
          "--raw-spacing",
          true,
          [](Options &o, const std::string &v) -> std::string {
            Vec3 s;
            if (!parseFloats(v, s.data(), 3) || s[0] <= 0.f || s[1] <= 0.f
                || s[2] <= 0.f)
              return expected(
                  "--raw-spacing", "three positive numbers x,y,z", v);
            o.rawSpacing = s;
            return {};
          }},
      {nullptr,
          "--grid",
          true,
          [](Options &o, const std::string &v) -> std::string {
            if (v.empty())
              return "--grid: expected a grid name";
            o.gridName = v;
            return {};
          }},
      {nullptr,
          "--tf-range",
          true,
          [](Options &o, const std::string &v) -> std::string {
            std::array<float, 2> range{};
            if (!parseFloats(v, range.data(), 2) || !(range[0] < range[1]))
              return expected("--tf-range", "LO,HI with LO < HI", v);
            o.transferFunction.valueRange = range;
            o.transferFunction.given = true;
            return {};
          }},
      {nullptr,
          "--tf-map",
          true,
          [](Options &o, const std::string &v) -> std::string {
            const std::string name = lowerCase(v);
            if (!scenes::findColorMap(name))
              return expected(
                  "--tf-map", "one of " + scenes::colorMapNames(), v);
            o.transferFunction.colorMap = name;
            o.transferFunction.given = true;
            return {};
          }},
      {nullptr,
          "--tf-opacity",
          true,
          [](Options &o, const std::string &v) -> std::string {
            // Enough control points for any ramp anyone types.
            constexpr size_t kMaxOpacities = 1024;
            const size_t count =
                size_t(std::count(v.begin(), v.end(), ',')) + 1;
            std::vector<float> opacities(std::min(count, kMaxOpacities));
            if (count > kMaxOpacities
                || !parseFloats(v, opacities.data(), int(count))
                || std::any_of(opacities.begin(), opacities.end(), [](float a) {
                     return !(a >= 0.f && a <= 1.f);
                   }))
              return expected("--tf-opacity",
                  "opacities V0,V1,... each from 0 to 1 (at most 1024)",
                  v);
            o.transferFunction.opacities = opacities;
            o.transferFunction.given = true;
            return {};
          }},
      {nullptr,
          "--tf-unit-distance",
          true,
          [](Options &o, const std::string &v) -> std::string {
            float d = 0.f;
            if (!parseFloats(v, &d, 1) || !(d > 0.f))
              return expected("--tf-unit-distance", "a positive distance", v);
            o.transferFunction.unitDistance = d;
            o.transferFunction.given = true;
            return {};
          }},
  };
}

// Options for messages and help.
std::vector<OptionSpec> generalOptions()
{
  return {
      {"-q",
          "--quiet",
          false,
          [](Options &o, const std::string &) -> std::string {
            o.quiet = true;
            return {};
          }},
      {"-v",
          "--verbose",
          false,
          [](Options &o, const std::string &) -> std::string {
            o.verbose = true;
            return {};
          }},
      {"-h",
          "--help",
          false,
          [](Options &o, const std::string &) -> std::string {
            o.help = true;
            return {};
          }},
      {nullptr,
          "--list-demos",
          false,
          [](Options &o, const std::string &) -> std::string {
            o.listDemos = true;
            return {};
          }},
  };
}

std::vector<OptionSpec> optionSpecs()
{
  std::vector<OptionSpec> all;
  for (auto group : {&inputAndImageOptions,
           &rendererOptions,
           &cameraOptions,
           &lightingOptions,
           &channelOptions,
           &deviceOptions,
           &volumeOptions,
           &generalOptions})
    for (OptionSpec &spec : group())
      all.push_back(std::move(spec));
  return all;
}

} // namespace

bool parseFloats(const std::string &text, float *values, int count)
{
  size_t start = 0;
  for (int i = 0; i < count; i++) {
    const size_t comma = text.find(',', start);
    const bool last = i + 1 == count;
    if (last != (comma == std::string::npos))
      return false;
    const std::string item =
        text.substr(start, last ? std::string::npos : comma - start);
    if (item.empty())
      return false;
    errno = 0;
    char *end = nullptr;
    const float value = std::strtof(item.c_str(), &end);
    if (errno != 0 || *end != '\0' || !std::isfinite(value))
      return false;
    values[i] = value;
    start = comma + 1;
  }
  return true;
}

bool isImagePath(const std::string &path)
{
  const std::string lower = lowerCase(path);
  for (const char *extension : {".png", ".exr", ".pfm"}) {
    const std::string e = extension;
    if (lower.size() > e.size()
        && lower.compare(lower.size() - e.size(), e.size(), e) == 0)
      return true;
  }
  return false;
}

ParseResult parseOptions(int argc, const char *const *argv)
{
  ParseResult result;
  Options &options = result.options;
  const std::vector<OptionSpec> specs = optionSpecs();
  bool onlyPositional = false;
  for (int i = 1; i < argc; i++) {
    const std::string argument = argv[i];
    if (onlyPositional || argument.empty() || argument[0] != '-'
        || argument == "-") {
      if (!options.scene.empty()) {
        result.error = "more than one scene given ('" + options.scene
                       + "' and '" + argument + "')";
        return result;
      }
      options.scene = argument;
      continue;
    }
    if (argument == "--") {
      onlyPositional = true;
      continue;
    }
    // "--name=value" carries its value; otherwise it is the next argument.
    std::string name = argument;
    std::optional<std::string> value;
    const size_t equals = argument.find('=');
    if (argument.starts_with("--") && equals != std::string::npos) {
      name = argument.substr(0, equals);
      value = argument.substr(equals + 1);
    }
    auto spec = std::find_if(specs.begin(), specs.end(), [&](const auto &s) {
      return name == s.longName || (s.shortName && name == s.shortName);
    });
    if (spec == specs.end()) {
      result.error = "unknown option '" + name + "'";
      return result;
    }
    if (!spec->takesValue && value) {
      result.error = name + " takes no value";
      return result;
    }
    if (spec->takesValue && !value) {
      if (i + 1 >= argc) {
        result.error = name + ": missing value";
        return result;
      }
      value = argv[++i];
    }
    result.error = spec->apply(options, value.value_or(""));
    if (!result.error.empty())
      return result;
  }
  if (options.scene.empty() && !options.help && !options.listDemos)
    result.error = "no scene given (a file, or demo:<name>; see --list-demos)";
  if (options.verbose && options.quiet)
    result.error = "--quiet and --verbose cannot be combined";
  return result;
}

std::string helpText()
{
  return R"(usage: prism-render SCENE [options]

Renders SCENE with an ANARI device (by default the prism device) and writes
the image. SCENE is a glTF 2.0 file (.gltf, .glb), an OBJ file (.obj, with
its .mtl), a raw volume grid (.raw, see --raw-dims), a NanoVDB file (.nvdb),
an ASCII NSI stream (recognised by its content, plain or gzip; rendered by
libnsi: its own screen and output drivers decide size, samples and files,
only --library applies) or demo:<name>.

Output
  -o, --output FILE      image to write: .png (8-bit sRGB), .exr or .pfm
                         (float); default <scene name>.png
  --size WxH             image size in pixels (default 1024x768)
  --spp N                samples per pixel, accumulated (in one render call
                         where the renderer has pixelSamples)
  --depth FILE           also write the depth channel (distance to the camera;
                         PNG: normalised, near is bright; EXR/PFM: the
                         distances, 0 where nothing was hit)
  --normal FILE          also write the normal channel (PNG: n * 0.5 + 0.5)
  --albedo FILE          also write the albedo channel
  --ids PREFIX           also write PREFIX.primitiveId.png, .objectId.png and
                         .instanceId.png, one false color per id
  --denoise              ask the renderer to denoise (KHR_RENDERER_DENOISE)

Rendering
  -r, --renderer SUBTYPE renderer subtype (default "default")
  -p, --param NAME=VALUE set a renderer parameter, typed by the device's
                         introspection: 0.5, 1,2,3, true, text
  --background R,G,B[,A] background color (linear)
  --env studio|none|FILE the environment that lights the scene besides its
                         own lights: a neutral studio, none (the scene's
                         lights only; black with the path tracer where it
                         has none), or an equirectangular .hdr/.exr image.
                         Default: files get the studio (at 1/4 when they
                         hold lights of their own), demos none
  --env-intensity SCALE  multiplies the environment's radiance (default 1)
  --env-rotate DEGREES   turns the environment about the scene's up axis
  -l, --library NAME     ANARI library to load (default prism): loads
                         libanari_library_NAME.so
      --trace FILE       record every ANARI call through the debug layer
                         into FILE (+ FILE.bin); anari-replay FILE replays it
      --mpi-partition    with a data-parallel library (prism_mpi, under
                         mpirun): each process keeps only its share of the
                         scene's surfaces and volumes (round robin), so the
                         processes render one scene split between them;
                         lights are kept by every process
  -d, --device SUBTYPE   device subtype (default "default")
  -t, --threads N        limit the device to N threads (TBB-based devices
                         and devices with a numThreads parameter)

Camera (default: the scene's camera, or framed to the world bounds)
  --eye X,Y,Z            camera position
  --at X,Y,Z             point looked at
  --up X,Y,Z             up direction
  --fovy DEGREES         vertical field of view
  --camera N             use glTF camera N instead of the first one

glTF files
  --variant NAME         use the glTF file's material variant NAME
                         (KHR_materials_variants) instead of its defaults
  --time SECONDS         pose the file's animations (nodes, skins, morph
                         weights) at this time (default: not played)

Raw volumes
  --raw-dims XxYxZ       voxel counts (else taken from a name like
                         skull_256x256x256_uint8.raw)
  --raw-type TYPE        uint8, int16, uint16, float32 or float64
  --raw-spacing X,Y,Z    voxel size (default 1,1,1)

NanoVDB files
  --grid NAME            the grid to render (default: the first scalar grid:
                         float, double, int32, Fp4, Fp8, Fp16 or FpN)

Volume transfer function (raw and NanoVDB files, demo:volume)
  --tf-range LO,HI       field values the color map spans (files: the
                         data's minimum and maximum)
  --tf-map NAME          color map: coolwarm (files' default), viridis,
                         inferno (demo:volume's) or grayscale
  --tf-opacity V0,V1,... opacities from 0 to 1, evenly spaced over the range
                         (files: 0,0.05,0.2,0.5,1)
  --tf-unit-distance D   distance over which an opacity is reached, in the
                         volume's world units (files: 1)

Other
  --bench N              render N frames and print min/median/max frame time
  --list-demos           list the built-in demo scenes
  -q, --quiet            no progress bar, no summary
  -v, --verbose          also show the device's informational messages
  -h, --help             this text

Examples
  prism-render demo:cornell-box -o cornell.png
  prism-render model.glb --size 1920x1080 --spp 64 -o model.exr
  prism-render model.gltf --renderer debug --param mode=Ng -o normals.png
  prism-render bunny.obj --eye 0,0.1,0.3 --at 0,0.1,0 --depth depth.pfm
  prism-render skull_256x256x256_uint8.raw -o skull.png
  prism-render cloud.nvdb --tf-map inferno --tf-opacity 0,0.3,1 -o cloud.png
  prism-render demo:volume --renderer raycast -o volume.png
  prism-render demo:instanced-forest --bench 20 -q
  prism-render demo:random-spheres --library helide -o helide.png

Exit status: 0 on success, 1 when the scene, device or output fails,
2 on a bad command line.
)";
}

} // namespace prism::render
