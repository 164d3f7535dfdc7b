#include "TraceFormat.h"

#include "anari/frontend/type_utility.h"

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unordered_map>

namespace prism::trace {
namespace {

// Every data type by name, built from the generated type table (no enum
// value is written here by hand).
const std::unordered_map<std::string, ANARIDataType> &typesByName()
{
  static const auto table = [] {
    std::unordered_map<std::string, ANARIDataType> out;
    for (int value = 0; value < 10000; ++value) {
      auto type = (ANARIDataType)value;
      if (anari::isValidDataType(type))
        out[typeName(type)] = type;
    }
    return out;
  }();
  return table;
}

bool isFloat32(ANARIDataType type)
{
  return std::strncmp(anari::toString(type), "ANARI_FLOAT32", 13) == 0;
}

bool isFloat64(ANARIDataType type)
{
  return std::strncmp(anari::toString(type), "ANARI_FLOAT64", 13) == 0;
}

} // namespace

std::string typeName(ANARIDataType type)
{
  const char *name = anari::toString(type);
  return std::strncmp(name, "ANARI_", 6) == 0 ? name + 6 : name;
}

bool typeFromName(const std::string &name, ANARIDataType &type)
{
  auto it = typesByName().find(name);
  if (it == typesByName().end())
    return false;
  type = it->second;
  return true;
}

bool isTraceable(ANARIDataType type)
{
  switch (int(type)) {
  case ANARI_VOID_POINTER:
  case ANARI_FUNCTION_POINTER:
  case ANARI_MEMORY_DELETER:
  case ANARI_STATUS_CALLBACK:
  case ANARI_FRAME_COMPLETION_CALLBACK:
  case ANARI_STRING_LIST:
  case ANARI_DATA_TYPE_LIST:
  case ANARI_PARAMETER_LIST:
  case ANARI_LIBRARY:
  case ANARI_UNKNOWN:
    return false;
  default:
    return anari::isValidDataType(type);
  }
}

std::string quote(const std::string &text)
{
  std::string out = "\"";
  for (char c : text) {
    switch (c) {
    case '"':
      out += "\\\"";
      break;
    case '\\':
      out += "\\\\";
      break;
    case '\n':
      out += "\\n";
      break;
    case '\t':
      out += "\\t";
      break;
    default:
      out += c;
    }
  }
  return out + "\"";
}

std::string encodeValue(ANARIDataType type, const void *value)
{
  const size_t size = anari::sizeOf(type);
  std::string out = "[";
  char buffer[40];
  if (isFloat32(type) || isFloat64(type)) {
    const int components = anari::componentsOf(type);
    for (int i = 0; i < components; ++i) {
      if (isFloat32(type)) {
        float v;
        std::memcpy(&v, (const char *)value + 4 * i, 4);
        std::snprintf(buffer, sizeof(buffer), "%.9g", v);
      } else {
        double v;
        std::memcpy(&v, (const char *)value + 8 * i, 8);
        std::snprintf(buffer, sizeof(buffer), "%.17g", v);
      }
      out.append(i ? " " : "").append(buffer);
    }
  } else {
    out += "x";
    for (size_t i = 0; i < size; ++i) {
      std::snprintf(
          buffer, sizeof(buffer), "%02x", ((const unsigned char *)value)[i]);
      out += buffer;
    }
  }
  return out + "]";
}

bool decodeValue(ANARIDataType type,
    const std::vector<std::string> &components,
    std::vector<unsigned char> &bytes)
{
  const size_t size = anari::sizeOf(type);
  bytes.assign(size, 0);
  if (isFloat32(type) || isFloat64(type)) {
    const size_t count = size_t(anari::componentsOf(type));
    if (components.size() != count)
      return false;
    for (size_t i = 0; i < count; ++i) {
      char *end = nullptr;
      const double v = std::strtod(components[i].c_str(), &end);
      if (!end || *end)
        return false;
      if (isFloat32(type)) {
        const float f = float(v); // %.9g reads back to the same float
        std::memcpy(bytes.data() + 4 * i, &f, 4);
      } else {
        std::memcpy(bytes.data() + 8 * i, &v, 8);
      }
    }
    return true;
  }
  if (components.size() != 1 || components[0].size() != 1 + 2 * size
      || components[0][0] != 'x')
    return false;
  for (size_t i = 0; i < size; ++i) {
    char hex[3] = {components[0][1 + 2 * i], components[0][2 + 2 * i], 0};
    char *end = nullptr;
    bytes[i] = (unsigned char)std::strtoul(hex, &end, 16);
    if (*end)
      return false;
  }
  return true;
}

uint64_t hashBytes(const void *data, size_t size)
{
  uint64_t hash = 14695981039346656037ull;
  auto *bytes = (const unsigned char *)data;
  for (size_t i = 0; i < size; ++i)
    hash = (hash ^ bytes[i]) * 1099511628211ull;
  return hash;
}

std::string hashName(uint64_t hash)
{
  char buffer[20];
  std::snprintf(buffer, sizeof(buffer), "h%016llx", (unsigned long long)hash);
  return buffer;
}

std::string reportLine(
    ANARIStatusSeverity severity, ANARIStatusCode code, const std::string &text)
{
  const char *severities[] = {"FATAL_ERROR",
      "ERROR",
      "WARNING",
      "PERFORMANCE_WARNING",
      "INFO",
      "DEBUG"};
  const char *codes[] = {"NO_ERROR",
      "UNKNOWN_ERROR",
      "INVALID_ARGUMENT",
      "INVALID_OPERATION",
      "OUT_OF_MEMORY",
      "UNSUPPORTED_DEVICE",
      "VERSION_MISMATCH"};
  std::string out = "Report ";
  out += severity >= 1 && severity <= 6 ? severities[severity - 1]
                                        : std::to_string(int(severity));
  out += " ";
  out += unsigned(code) < 7 ? codes[code] : std::to_string(int(code));
  std::string stable;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text.compare(i, 2, "0x") == 0 && i + 2 < text.size()
        && std::isxdigit((unsigned char)text[i + 2])) {
      stable += "0x?";
      i += 2;
      while (i + 1 < text.size() && std::isxdigit((unsigned char)text[i + 1]))
        ++i;
    } else {
      stable += text[i];
    }
  }
  return out + " " + quote(stable);
}

bool tokenize(
    const std::string &line, std::vector<Token> &tokens, std::string &error)
{
  tokens.clear();
  size_t i = 0;
  while (i < line.size()) {
    const char c = line[i];
    if (c == ' ' || c == '\t' || c == '\r') {
      ++i;
    } else if (c == '#') {
      break; // a comment to the end of the line
    } else if (c == '[' || c == ']') {
      tokens.push_back({c == '[' ? Token::kOpen : Token::kClose, {}});
      ++i;
    } else if (c == '"') {
      Token token{Token::kString, {}};
      for (++i; i < line.size() && line[i] != '"'; ++i) {
        if (line[i] == '\\' && i + 1 < line.size()) {
          const char e = line[++i];
          token.text += e == 'n' ? '\n' : e == 't' ? '\t' : e == 'r' ? '\r' : e;
        } else {
          token.text += line[i];
        }
      }
      if (i >= line.size()) {
        error = "unterminated string";
        return false;
      }
      ++i;
      tokens.push_back(std::move(token));
    } else {
      Token token{Token::kWord, {}};
      while (i < line.size() && line[i] != ' ' && line[i] != '\t'
             && line[i] != '[' && line[i] != ']' && line[i] != '"'
             && line[i] != '#' && line[i] != '\r')
        token.text += line[i++];
      tokens.push_back(std::move(token));
    }
  }
  return true;
}

} // namespace prism::trace
