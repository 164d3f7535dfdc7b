// nsi-render: reads ASCII NSI streams (plain or gzip) and renders them
// through libnsi on an ANARI library (prism unless --library says otherwise).
// The stream's own RenderControl calls start the render; a stream without
// them is started and waited for here. With --write, nothing is rendered:
// the calls the streams make are written to one ASCII stream (includes
// inlined), which checks and normalises streams.
#include <nsi.hpp>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

int g_errors = 0;

void onMessage(void *, int level, int, const char *message)
{
  if (level >= NSIErrError)
    ++g_errors;
  const char *prefix = level >= NSIErrError     ? "error: "
                       : level == NSIErrWarning ? "warning: "
                                                : "";
  std::fprintf(stderr, "nsi-render: %s%s\n", prefix, message);
}

void usage(std::FILE *out)
{
  std::fputs(
      "usage: nsi-render [--library NAME] [--start] [--write OUT] FILE.nsi...\n"
      "  --library NAME  the ANARI library to render with (default: prism)\n"
      "  --start         start and wait for a render after reading the files\n"
      "                  (for streams without RenderControl calls)\n"
      "  --write OUT     render nothing: write the calls the files make to\n"
      "                  the ASCII stream OUT (\"stdout\" for the terminal)\n",
      out);
}

} // namespace

int main(int argc, char **argv)
{
  std::string library, writeTo;
  bool start = false;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      usage(stdout);
      return 0;
    } else if (arg == "--library" && i + 1 < argc) {
      library = argv[++i];
    } else if (arg == "--write" && i + 1 < argc) {
      writeTo = argv[++i];
    } else if (arg == "--start") {
      start = true;
    } else if (!arg.empty() && arg[0] == '-') {
      usage(stderr);
      return 2;
    } else {
      files.push_back(arg);
    }
  }
  if (files.empty()) {
    usage(stderr);
    return 2;
  }

  NSI::ArgumentList begin;
  begin.addPointer("errorhandler", reinterpret_cast<const void *>(&onMessage));
  if (!library.empty())
    begin.addString("anarilibrary", library.c_str());
  if (!writeTo.empty()) {
    begin.addString("type", "apistream")
        .addString("streamfilename", writeTo.c_str())
        .addString("executeprocedurals", "apistream");
  }
  NSI::Context nsi;
  if (!nsi.Begin(begin)) {
    std::fputs("nsi-render: cannot begin an NSI context\n", stderr);
    return 1;
  }
  for (const std::string &file : files) {
    NSI::ArgumentList evaluate;
    evaluate.addString("type", "apistream").addString("filename", file.c_str());
    nsi.Evaluate(evaluate);
  }
  if (start) {
    nsi.RenderControl(NSI::ArgumentList().addString("action", "start"));
    nsi.RenderControl(NSI::ArgumentList().addString("action", "wait"));
  }
  nsi.End();
  return g_errors ? 1 : 0;
}
