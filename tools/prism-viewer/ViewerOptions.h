// prism-viewer's command line.
#pragma once

#include <cstdint>
#include <string>

namespace prism::viewer {

struct ViewerOptions
{
  std::string scene;            // a file or demo:NAME; empty: none yet
  std::string library{"prism"}; // --library, else $ANARI_LIBRARY
  std::string deviceSubtype{"default"};
  std::string renderer{"default"};
  uint32_t width{1024}, height{768}; // --size WxH, the window's
  std::string script;                // --script FILE
  int cameraIndex{-1};     // --camera N: the glTF camera to start from
  uint32_t sampleLimit{0}; // --spp-limit N (0: none)
  uint32_t threads{0};     // --threads N: the device's numThreads (0: its own)
  float interactionScale{0.5f}; // --interaction-scale F in (0, 1]
  std::string traceFile;        // --trace FILE: the validation layer's
  std::string frameTimes; // --frame-times FILE: each UI frame's interval (ms)
  bool panelsOpen{false}; // --panels open: every panel section starts open
  bool verbose{false};
  bool help{false};
};

struct ParsedOptions
{
  ViewerOptions options;
  std::string error; // empty on success, naming the option

  bool ok() const
  {
    return error.empty();
  }
};

// `environmentLibrary` is $ANARI_LIBRARY (null: unset).
ParsedOptions parseViewerOptions(
    int argc, const char *const *argv, const char *environmentLibrary);

std::string viewerHelp();

} // namespace prism::viewer
