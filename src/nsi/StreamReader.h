// Reads an ASCII NSI stream and replays it as calls on a context through the
// C API. The stream is not line based: a statement ends at the next keyword.
// Errors are reported with the line and the reader carries on at the next
// keyword; nothing in the text can crash it.
#pragma once

#include "nsi.h"

#include <functional>
#include <string>

namespace prism::nsi {

struct Value;

class StreamReader
{
 public:
  using Report = std::function<void(int level, const std::string &)>;

  StreamReader(NSIContext_t context, Report report, std::string sourceName);

  void read(const std::string &text);

 private:
  bool readParameter(
      class StreamTokenizer &tokens, std::string &name, Value &value);
  void problem(int line, const std::string &what);

  NSIContext_t m_context;
  Report m_report;
  std::string m_sourceName;
};

// Parses a type spec ("v point", "int[2]", "i float") into `value`'s type,
// flags and arraylength; false if it names no type.
bool parseTypeSpec(const std::string &spec, Value &value);

} // namespace prism::nsi
