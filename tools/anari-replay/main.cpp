// anari-replay: replays a trace of the debug layer (docs/debug-layer.md) on
// any ANARI library, checks every image it maps against the one recorded,
// and can write them.
#include "Replayer.h"

#include <cstdio>
#include <filesystem>
#include <string>

namespace {

const char *kUsage =
    "usage: anari-replay TRACE [--library NAME] [--write-frames DIR]\n"
    "                    [--check-reports]\n"
    "Replays TRACE (and TRACE.bin) through libanari on NAME (default: the\n"
    "library the trace was recorded on). Every frame the trace mapped is\n"
    "compared with the recorded one; exit status 0 if all are the same bit\n"
    "for bit, 2 if any differs, 1 on an error. --write-frames writes each\n"
    "mapped channel to DIR, made if need be (.raw bytes; FLOAT32_VEC4 also\n"
    "as .exr); a file it cannot write is an error.\n"
    "--check-reports replays through the debug layer wrapped around NAME,\n"
    "with the calls the layer refused, and exits 3 unless the layer makes\n"
    "the same reports (warnings and errors) as recorded, in the same order.\n";

} // namespace

int main(int argc, char **argv)
{
  prism::replay::Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if ((arg == "--library" || arg == "--write-frames") && i + 1 < argc) {
      (arg == "--library" ? options.library : options.frameDirectory) =
          argv[++i];
    } else if (arg == "--check-reports") {
      options.checkReports = true;
    } else if (arg == "--help" || arg == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (options.tracePath.empty() && !arg.empty() && arg[0] != '-') {
      options.tracePath = arg;
    } else {
      std::fprintf(
          stderr, "anari-replay: unexpected '%s'\n%s", arg.c_str(), kUsage);
      return 1;
    }
  }
  if (options.tracePath.empty()) {
    std::fputs(kUsage, stderr);
    return 1;
  }
  if (!options.frameDirectory.empty()) {
    // Made now, so a folder that cannot be made fails before the replay.
    std::error_code error;
    std::filesystem::create_directories(options.frameDirectory, error);
    if (!std::filesystem::is_directory(options.frameDirectory)) {
      std::fprintf(stderr,
          "anari-replay: --write-frames: cannot make the folder '%s'%s%s\n",
          options.frameDirectory.c_str(),
          error ? ": " : "",
          error ? error.message().c_str() : "");
      return 1;
    }
  }
  prism::replay::Replayer replayer(options);
  if (!replayer.run()) {
    std::fprintf(stderr,
        "anari-replay: %s: %s\n",
        options.tracePath.c_str(),
        replayer.error().c_str());
    return 1;
  }
  const auto &s = replayer.summary();
  std::printf(
      "replayed %llu calls: %d frame(s) the same bit for bit, %d "
      "different\n",
      (unsigned long long)s.calls,
      s.framesSame,
      s.framesDifferent);
  if (options.checkReports) {
    std::printf("%llu report(s) recorded, %llu replayed: %s\n",
        (unsigned long long)s.reportsRecorded,
        (unsigned long long)s.reportsReplayed,
        s.reportsDifference.empty() ? "the same" : s.reportsDifference.c_str());
  }
  if (s.framesDifferent)
    return 2;
  return s.reportsDifference.empty() ? 0 : 3;
}
