#include "StreamWriter.h"

#include <unistd.h>
#include <charconv>
#include <cstring>
#include <sstream>

namespace prism::nsi {

std::string quoted(const std::string &text)
{
  std::string out = "\"";
  for (unsigned char c : text) {
    if (c == '"')
      out += "\\\"";
    else if (c == '\\')
      out += "\\\\";
    else if (c == '\n')
      out += "\\n";
    else if (c == '\t')
      out += "\\t";
    else if (c < 0x20) {
      char octal[5];
      std::snprintf(octal, sizeof octal, "\\%03o", unsigned(c));
      out += octal;
    } else {
      out += char(c);
    }
  }
  out += '"';
  return out;
}

std::string typeSpec(const Value &value)
{
  const char *base = nullptr;
  switch (value.type) {
  case NSITypeFloat:
    base = "float";
    break;
  case NSITypeDouble:
    base = "double";
    break;
  case NSITypeInteger:
    base = "int";
    break;
  case NSITypeInt64:
    base = "int64";
    break;
  case NSITypeString:
    base = "string";
    break;
  case NSITypeColor:
    base = "color";
    break;
  case NSITypePoint:
    base = "point";
    break;
  case NSITypeVector:
    base = "vector";
    break;
  case NSITypeNormal:
    base = "normal";
    break;
  case NSITypeMatrix:
    base = "matrix";
    break;
  case NSITypeDoubleMatrix:
    base = "doublematrix";
    break;
  case NSITypeHPoint:
    base = "hpoint";
    break;
  default:
    return {};
  }
  std::string flags;
  if (value.flags & NSIParamPerVertex)
    flags += 'v';
  if (value.flags & NSIParamPerFace)
    flags += 'f';
  if (value.flags & NSIParamInterpolateLinear)
    flags += 'l';
  // A stream, not string concatenation: GCC 12 raises a false -Wrestrict.
  std::ostringstream spec;
  if (!flags.empty())
    spec << flags << ' ';
  spec << base;
  if (value.flags & NSIParamIsArray)
    spec << '[' << value.arraylength << ']';
  return spec.str();
}

std::string formatFloat(float value)
{
  char text[64];
  auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

std::string formatDouble(double value)
{
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

StreamWriter::StreamWriter(const std::string &target, bool gzip)
{
  if (target == "stdout") {
    m_file = stdout;
  } else if (target == "stderr") {
    m_file = stderr;
  } else if (!gzip) {
    m_file = std::fopen(target.c_str(), "wb");
    m_owned = m_file != nullptr;
  }
  if (gzip) {
    // The standard streams are compressed through a duplicate descriptor,
    // so closing it leaves them open.
    m_gzip = m_file ? gzdopen(dup(fileno(m_file)), "wb")
                    : gzopen(target.c_str(), "wb");
    m_file = nullptr;
    m_owned = false;
  }
  write("# NSI ASCII stream\n# written by Prism libnsi\n");
}

StreamWriter::~StreamWriter()
{
  if (m_gzip)
    gzclose(m_gzip);
  if (m_owned)
    std::fclose(m_file);
  else if (m_file)
    std::fflush(m_file);
}

void StreamWriter::write(const std::string &text)
{
  if (m_gzip)
    gzwrite(m_gzip, text.data(), unsigned(text.size()));
  else if (m_file)
    std::fwrite(text.data(), 1, text.size(), m_file);
}

void StreamWriter::flush()
{
  // gzip streams are only complete when closed; flushing them mid-stream
  // would cost compression for nothing.
  if (m_file)
    std::fflush(m_file);
}

void StreamWriter::statement(const char *keyword,
    const std::vector<std::string> &operands,
    const ParameterList &params,
    std::optional<double> time)
{
  if (!ok())
    return;
  std::string line = keyword;
  for (auto &operand : operands) {
    line += ' ';
    line += quoted(operand);
  }
  if (time) {
    line += ' ';
    line += formatDouble(*time);
  }
  line += "\n";
  write(line);
  for (auto &param : params.values)
    parameter(param);
  flush();
}

void StreamWriter::parameter(const NamedValue &param)
{
  const Value &v = param.value;
  const std::string spec = typeSpec(v);
  if (spec.empty())
    return; // pointers: meaningless in another process
  std::string line = "  ";
  line += quoted(param.name);
  line += ' ';
  line += quoted(spec);
  line += ' ';
  line += std::to_string(v.count);
  line += " [";
  if (v.type == NSITypeString) {
    for (auto &s : v.strings) {
      line += ' ';
      line += quoted(s);
    }
  } else {
    const size_t n = v.count * v.valuesPerItem() * Value::componentsOf(v.type);
    for (size_t i = 0; i < n; ++i) {
      line += " ";
      switch (v.type) {
      case NSITypeInteger: {
        int32_t x;
        std::memcpy(&x, v.bytes.data() + 4 * i, 4);
        line += std::to_string(x);
        break;
      }
      case NSITypeInt64: {
        int64_t x;
        std::memcpy(&x, v.bytes.data() + 8 * i, 8);
        line += std::to_string(x);
        break;
      }
      case NSITypeDouble:
      case NSITypeDoubleMatrix: {
        double x;
        std::memcpy(&x, v.bytes.data() + 8 * i, 8);
        line += formatDouble(x);
        break;
      }
      default: {
        float x;
        std::memcpy(&x, v.bytes.data() + 4 * i, 4);
        line += formatFloat(x);
        break;
      }
      }
    }
  }
  line += " ]\n";
  write(line);
}

} // namespace prism::nsi
