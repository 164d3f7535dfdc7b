// libFuzzer target: any bytes as a trace of the debug layer and its side
// file, replayed by anari-replay's reader on the prism device (see
// README.md). Nothing may crash, leak, hang or read out of bounds.
#include "Replayer.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

namespace {

// Where the trace text ends and the side file's bytes begin (a comment
// line, so a seed is a trace as it stands).
const std::string kSideFileMark = "\n#@bin\n";
// A first line asking for the layer's own checks (--check-reports).
const std::string kCheckReportsMark = "# check-reports\n";

// The input as files, since traces are read from files; removed when the
// process ends.
struct InputFiles
{
  std::string trace =
      "/tmp/prism-fuzz-trace-" + std::to_string(::getpid()) + ".trace";
  std::string side = trace + ".bin";
  ~InputFiles()
  {
    std::remove(trace.c_str());
    std::remove(side.c_str());
  }
};

bool write(const std::string &path, const char *data, size_t size)
{
  std::FILE *file = std::fopen(path.c_str(), "wb");
  if (!file)
    return false;
  const bool written = std::fwrite(data, 1, size, file) == size;
  return std::fclose(file) == 0 && written;
}

// The libraries a replay loads, held open for the whole process: libFuzzer
// reads their coverage counters after every input, and a library that
// libanari unloads at the end of a replay would take its counters along.
void keepLibrariesLoaded()
{
  static const bool loaded = [] {
    for (const char *name :
        {"libanari_library_prism.so", "libanari_library_debug.so"})
      dlopen(name, RTLD_NOW | RTLD_NODELETE);
    return true;
  }();
  (void)loaded;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  static const InputFiles files;
  keepLibrariesLoaded();
  const std::string input((const char *)data, size);
  const size_t mark = input.find(kSideFileMark);
  const size_t textSize = mark == std::string::npos ? size : mark;
  const size_t sideStart =
      mark == std::string::npos ? size : mark + kSideFileMark.size();
  if (!write(files.trace, input.data(), textSize)
      || !write(files.side, input.data() + sideStart, size - sideStart))
    return 0;
  prism::replay::Options options;
  options.tracePath = files.trace;
  options.library = "prism"; // never a library the input names
  options.checkReports =
      input.compare(0, kCheckReportsMark.size(), kCheckReportsMark) == 0;
  // Cheap inputs: no frame renders and no array passes 1 MiB, so an input
  // takes milliseconds; the reader's checks are what is fuzzed here (the
  // device's frames are fuzz_api's).
  options.renderFrames = false;
  options.maxArrayBytes = 1 << 20;
  options.printMessages = false;
  prism::replay::Replayer replayer(options);
  replayer.run();
  return 0;
}
