#include "SceneSource.h"

#ifdef PRISM_SCENE_IO_HAS_ZLIB
#include <zlib.h>
#endif

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace prism::scene_io {

namespace {

// The first bytes of the file, inflated when it is gzip (where zlib is).
std::string head(const std::string &path)
{
  char buffer[4096];
  int n = 0;
#ifdef PRISM_SCENE_IO_HAS_ZLIB
  gzFile file = gzopen(path.c_str(), "rb");
  if (!file)
    return {};
  n = gzread(file, buffer, sizeof buffer);
  gzclose(file);
#else
  std::FILE *file = std::fopen(path.c_str(), "rb");
  if (!file)
    return {};
  n = int(std::fread(buffer, 1, sizeof buffer, file));
  std::fclose(file);
#endif
  return n > 0 ? std::string(buffer, size_t(n)) : std::string();
}

} // namespace

bool isNsiScene(const std::string &path)
{
  const std::string text = head(path);
  size_t at = 0;
  while (at < text.size()) {
    if (std::isspace((unsigned char)text[at])) {
      ++at;
    } else if (text[at] == '#') {
      at = text.find('\n', at);
      if (at == std::string::npos)
        return false;
    } else {
      break;
    }
  }
  size_t end = at;
  while (end < text.size() && std::isalpha((unsigned char)text[end]))
    ++end;
  const std::string word = text.substr(at, end - at);
  for (const char *keyword : {"Create",
           "Delete",
           "SetAttribute",
           "SetAttributeAtTime",
           "DeleteAttribute",
           "Connect",
           "Disconnect",
           "Evaluate",
           "RenderControl"}) {
    if (word == keyword)
      return true;
  }
  return false;
}

namespace {

std::string lowerExtension(const std::string &path)
{
  std::string e = std::filesystem::path(path).extension().string();
  for (char &c : e)
    c = char(std::tolower((unsigned char)c));
  return e;
}

SourceResult demoSource(const std::string &name)
{
  SourceResult result;
  result.source.format = SceneFormat::Demo;
  result.source.name = name;
  result.source.demo = scenes::findDemoScene(name);
  if (!result.source.demo) {
    std::string names;
    for (const scenes::DemoScene &d : scenes::demoScenes())
      names += std::string(names.empty() ? "" : ", ") + d.name;
    result.error = "unknown demo scene '" + name + "' (demos: " + names + ")";
    result.badName = true;
  }
  return result;
}

} // namespace

SourceResult identifySceneSource(const std::string &text)
{
  if (text.starts_with("demo:"))
    return demoSource(text.substr(5));
  SourceResult result;
  SceneSource &source = result.source;
  source.path = text;
  source.name = std::filesystem::path(text).stem().string();
  std::error_code ec;
  if (std::filesystem::is_directory(text, ec)) {
    result.error = "cannot read scene '" + text + "': it is a directory";
    return result;
  }
  if (isNsiScene(text)) {
    source.format = SceneFormat::Nsi;
    return result;
  }
  const std::string extension = lowerExtension(text);
  if (extension == ".gltf" || extension == ".glb")
    source.format = SceneFormat::Gltf;
  else if (extension == ".obj")
    source.format = SceneFormat::Obj;
  else if (extension == ".raw")
    source.format = SceneFormat::Raw;
  else if (extension == ".nvdb")
    source.format = SceneFormat::NanoVdb;
  else {
    result.error = "'" + text
                   + "': unknown scene file type (expected .gltf, .glb, "
                     ".obj, .raw, .nvdb, an NSI stream or demo:<name>)";
    result.badName = true;
    return result;
  }
  std::FILE *file = std::fopen(text.c_str(), "rb");
  if (!file) {
    result.error = "cannot open scene '" + text + "': " + std::strerror(errno);
    return result;
  }
  std::fclose(file);
  return result;
}

bool hasVolumeStyle(const SceneSource &source)
{
  return source.format == SceneFormat::Raw
         || source.format == SceneFormat::NanoVdb
         || (source.demo && source.demo->buildWithVolumeStyle);
}

} // namespace prism::scene_io
