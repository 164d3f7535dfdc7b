// What a scene source names: a built-in demo ("demo:NAME") or a file, whose
// format its extension tells (NSI streams: their content). Checked before a
// device is touched, so a bad name costs nothing.
#pragma once

#include "DemoScenes.h"

#include <string>

namespace prism::scene_io {

enum class SceneFormat { Demo, Gltf, Obj, Raw, NanoVdb, Nsi };

struct SceneSource
{
  SceneFormat format{SceneFormat::Demo};
  std::string path;                       // the file; empty for demos
  const scenes::DemoScene *demo{nullptr}; // for SceneFormat::Demo
  std::string name; // the demo's name or the file's stem (output names)
};

struct SourceResult
{
  SceneSource source;
  std::string error; // empty on success; names the source and the problem
  // True when the name itself is wrong (an unknown demo or file type), as
  // opposed to a file that cannot be read.
  bool badName{false};

  bool ok() const
  {
    return error.empty();
  }
};

// The scene `text` names, or why there is none: an unknown demo, a file
// type no loader reads, a folder, a file that cannot be opened.
SourceResult identifySceneSource(const std::string &text);

// Whether `path` holds an ASCII NSI stream (plain or gzip): after blanks
// and '#' comments its text starts with an NSI statement keyword. (".nsi"
// also names NSIS installer scripts, so the name decides nothing.)
bool isNsiScene(const std::string &path);

// Whether the source is a volume whose transfer function the caller may
// restyle (volume files, demos with a volume style).
bool hasVolumeStyle(const SceneSource &source);

} // namespace prism::scene_io
