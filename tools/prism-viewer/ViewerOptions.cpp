#include "ViewerOptions.h"

#include <charconv>
#include <cmath>
#include <cstring>

namespace prism::viewer {
namespace {

bool readSize(const std::string &text, uint32_t &w, uint32_t &h)
{
  const size_t x = text.find('x');
  if (x == std::string::npos)
    return false;
  const char *s = text.data();
  const auto a = std::from_chars(s, s + x, w);
  const auto b = std::from_chars(s + x + 1, s + text.size(), h);
  return a.ec == std::errc() && a.ptr == s + x && b.ec == std::errc()
         && b.ptr == s + text.size() && w >= 16 && h >= 16 && w <= 16384
         && h <= 16384;
}

} // namespace

ParsedOptions parseViewerOptions(
    int argc, const char *const *argv, const char *environmentLibrary)
{
  ParsedOptions parsed;
  ViewerOptions &o = parsed.options;
  if (environmentLibrary && *environmentLibrary)
    o.library = environmentLibrary;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&](std::string &out) {
      if (i + 1 >= argc) {
        parsed.error = arg + " needs a value";
        return false;
      }
      out = argv[++i];
      return true;
    };
    std::string text;
    if (arg == "-h" || arg == "--help") {
      o.help = true;
    } else if (arg == "-v" || arg == "--verbose") {
      o.verbose = true;
    } else if (arg == "--library" || arg == "-l") {
      if (!value(o.library))
        return parsed;
    } else if (arg == "--device") {
      if (!value(o.deviceSubtype))
        return parsed;
    } else if (arg == "--renderer" || arg == "-r") {
      if (!value(o.renderer))
        return parsed;
    } else if (arg == "--script") {
      if (!value(o.script))
        return parsed;
    } else if (arg == "--trace") {
      if (!value(o.traceFile))
        return parsed;
    } else if (arg == "--panels") {
      if (!value(text))
        return parsed;
      if (text != "open" && text != "folded") {
        parsed.error = "--panels is open or folded, not '" + text + "'";
        return parsed;
      }
      o.panelsOpen = text == "open";
    } else if (arg == "--frame-times") {
      if (!value(o.frameTimes))
        return parsed;
    } else if (arg == "--size") {
      if (!value(text))
        return parsed;
      if (!readSize(text, o.width, o.height)) {
        parsed.error =
            "--size takes WxH (16 to 16384 each), not '" + text + "'";
        return parsed;
      }
    } else if (arg == "--spp-limit") {
      if (!value(text))
        return parsed;
      const auto r = std::from_chars(
          text.data(), text.data() + text.size(), o.sampleLimit);
      if (r.ec != std::errc() || r.ptr != text.data() + text.size()) {
        parsed.error = "--spp-limit takes a sample count, not '" + text + "'";
        return parsed;
      }
    } else if (arg == "--camera") {
      if (!value(text))
        return parsed;
      const auto r = std::from_chars(
          text.data(), text.data() + text.size(), o.cameraIndex);
      if (r.ec != std::errc() || r.ptr != text.data() + text.size()
          || o.cameraIndex < 0) {
        parsed.error =
            "--camera takes a camera index (0 or more), not '" + text + "'";
        return parsed;
      }
    } else if (arg == "--threads") {
      if (!value(text))
        return parsed;
      const auto r =
          std::from_chars(text.data(), text.data() + text.size(), o.threads);
      if (r.ec != std::errc() || r.ptr != text.data() + text.size()
          || o.threads == 0) {
        parsed.error =
            "--threads takes a count (1 or more), not '" + text + "'";
        return parsed;
      }
    } else if (arg == "--interaction-scale") {
      if (!value(text))
        return parsed;
      const auto r = std::from_chars(
          text.data(), text.data() + text.size(), o.interactionScale);
      if (r.ec != std::errc() || r.ptr != text.data() + text.size()
          || !(o.interactionScale > 0.f && o.interactionScale <= 1.f)) {
        parsed.error =
            "--interaction-scale takes a number in (0, 1], not '" + text + "'";
        return parsed;
      }
    } else if (!arg.empty() && arg[0] == '-') {
      parsed.error = "unknown option '" + arg + "'";
      return parsed;
    } else if (o.scene.empty()) {
      o.scene = arg;
    } else {
      parsed.error = "one scene only ('" + o.scene + "' and '" + arg + "')";
      return parsed;
    }
  }
  return parsed;
}

std::string viewerHelp()
{
  return R"(usage: prism-viewer [SCENE] [options]

Shows SCENE (glTF/GLB, OBJ, .raw, .nvdb, demo:NAME; or drop a file on the
window) with any ANARI library, refining progressively.

  --library NAME          ANARI library (default $ANARI_LIBRARY, else prism)
  --device SUBTYPE        device subtype (default: default)
  --renderer NAME         renderer subtype (default: default)
  --size WxH              window size (default 1024x768)
  --camera N              start from the glTF file's camera N (default: its
                          first; F returns to it)
  --spp-limit N           stop refining at N samples (default: never)
  --interaction-scale F   resolution scale while the camera moves (0.5)
  --threads N             render threads, where the device takes numThreads
                          (leaving a core to the window keeps it fluid)
  --script FILE           replay UI actions from FILE (docs/viewer.md)
  --trace FILE            record an ANARI trace through the validation layer
  --panels open|folded    every panel section open at the start (default:
                          folded; scripts start with the whole panel folded)
  --frame-times FILE      write each window frame's interval and drawing
                          time in ms (bench/)
  -v, --verbose           every device message
  -h, --help              this text

Mouse: left drag orbits, right drag (or shift+left) pans, wheel zooms,
click picks, double-click focuses depth of field. Keys: W A S D Q E fly,
F frames the scene.
)";
}

} // namespace prism::viewer
