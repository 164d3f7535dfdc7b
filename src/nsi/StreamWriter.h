// Writes NSI calls as an ASCII stream: one statement per call, the keyword
// and its operands on one line, each parameter on its own indented line.
// Pointer parameters have no stream form and are left out.
#pragma once

#include "ParameterList.h"

#include <zlib.h>

#include <cstdio>
#include <optional>
#include <string>

namespace prism::nsi {

class StreamWriter
{
 public:
  // `target` is a file name, "stdout" or "stderr"; `gzip` compresses what
  // is written. Check ok() afterwards.
  explicit StreamWriter(const std::string &target, bool gzip = false);
  ~StreamWriter();
  StreamWriter(const StreamWriter &) = delete;
  StreamWriter &operator=(const StreamWriter &) = delete;

  bool ok() const
  {
    return m_file != nullptr || m_gzip != nullptr;
  }

  // `operands` are the strings after the keyword; `time` is written after
  // them for SetAttributeAtTime.
  void statement(const char *keyword,
      const std::vector<std::string> &operands,
      const ParameterList &params,
      std::optional<double> time = {});

 private:
  void parameter(const NamedValue &param);
  void write(const std::string &text);
  void flush();

  std::FILE *m_file{nullptr};
  gzFile m_gzip{nullptr}; // instead of m_file when compressing
  bool m_owned{false};
};

// A string in stream syntax: quoted, with \" \\ \n \t escapes and other
// bytes below 0x20 as three octal digits.
std::string quoted(const std::string &text);
// The stream's name for a type with its flags and array size, e.g.
// "v point" or "int[2]"; empty for types without one (pointers).
std::string typeSpec(const Value &value);
// Numbers as the reader reads them back exactly.
std::string formatFloat(float value);
std::string formatDouble(double value);

} // namespace prism::nsi
