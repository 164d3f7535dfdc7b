// libFuzzer target: any bytes as an ASCII NSI stream, read twice: into a
// render context (graph edits; `start` resolves the scene, then fails to
// load an ANARI library that does not exist, so nothing renders) and into
// a stream-writing context (the writer). Nothing may crash, leak or hang.
#include <nsi.hpp>

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

namespace {

void quiet(void *, int, int, const char *) {}

// The input as a file, since streams are read from files; removed when
// the process ends.
struct InputFile
{
  std::string path =
      "/tmp/prism-fuzz-nsi-" + std::to_string(::getpid()) + ".nsi";
  ~InputFile()
  {
    std::remove(path.c_str());
  }
};

std::string writeInput(const uint8_t *data, size_t size)
{
  static const InputFile input;
  std::FILE *file = std::fopen(input.path.c_str(), "wb");
  if (!file)
    return {};
  std::fwrite(data, 1, size, file);
  std::fclose(file);
  return input.path;
}

void readInto(NSI::ArgumentList &begin, const std::string &path)
{
  begin.addPointer("errorhandler", reinterpret_cast<const void *>(&quiet));
  NSI::Context nsi;
  if (!nsi.Begin(begin))
    return;
  NSI::ArgumentList evaluate;
  evaluate.addString("type", "apistream").addString("filename", path.c_str());
  nsi.Evaluate(evaluate);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  const std::string path = writeInput(data, size);
  if (path.empty())
    return 0;
  NSI::ArgumentList render;
  render.addString("anarilibrary", "prism-fuzz-no-such-library");
  readInto(render, path);
  NSI::ArgumentList stream;
  stream.addString("type", "apistream")
      .addString("streamfilename", "/dev/null");
  readInto(stream, path);
  return 0;
}
