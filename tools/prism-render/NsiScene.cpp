#include "NsiScene.h"

#include "Console.h"

#ifdef PRISM_RENDER_HAS_ZLIB
#include <zlib.h>
#endif

#include <atomic>
#include <cctype>
#include <cstdio>

#ifdef PRISM_RENDER_HAS_NSI
#include <nsi.hpp>
#endif

namespace prism::render {

namespace {

// The first bytes of the file, inflated when it is gzip (where zlib is).
std::string head(const std::string &path)
{
  char buffer[4096];
  int n = 0;
#ifdef PRISM_RENDER_HAS_ZLIB
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

#ifdef PRISM_RENDER_HAS_NSI

namespace {
std::atomic<int> g_nsiErrors{0};

void onNsiMessage(void *, int level, int, const char *message)
{
  const std::string text = std::string("nsi: ") + (message ? message : "");
  if (level >= NSIErrError) {
    ++g_nsiErrors;
    console::error(text);
  } else if (level == NSIErrWarning) {
    console::warning(text);
  } else {
    console::message(text);
  }
}
} // namespace

int renderNsiScene(const Options &options)
{
  g_nsiErrors = 0;
  NSI::ArgumentList begin;
  begin.addPointer(
      "errorhandler", reinterpret_cast<const void *>(&onNsiMessage));
  begin.addString("anarilibrary", options.library.c_str());
  NSI::Context nsi;
  if (!nsi.Begin(begin)) {
    console::error("cannot begin an NSI context");
    return 1;
  }
  NSI::ArgumentList evaluate;
  evaluate.addString("type", "apistream")
      .addString("filename", options.scene.c_str());
  nsi.Evaluate(evaluate);
  nsi.End(); // waits for a render the stream started
  return g_nsiErrors ? 1 : 0;
}

#else

int renderNsiScene(const Options &options)
{
  console::error(
      "'" + options.scene
      + "' is an NSI scene, and this prism-render was built without libnsi");
  return 1;
}

#endif

} // namespace prism::render
