#include "NsiRender.h"

#include "Console.h"

#include <atomic>

#ifdef PRISM_RENDER_HAS_NSI
#include <nsi.hpp>
#endif

namespace prism::render {

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
