#include "PathExpansion.h"

#include <cstdlib>

namespace prism::nsi {

std::string expandPath(const std::string &path)
{
  std::string out;
  size_t at = 0;
  while (at < path.size()) {
    const size_t open = path.find("${", at);
    if (open == std::string::npos)
      break;
    const size_t close = path.find('}', open + 2);
    if (close == std::string::npos)
      break;
    out.append(path, at, open - at);
    const std::string name = path.substr(open + 2, close - open - 2);
    const char *value = name.empty() ? nullptr : std::getenv(name.c_str());
    if (value)
      out += value;
    else
      out.append(path, open, close + 1 - open);
    at = close + 1;
  }
  out.append(path, at, std::string::npos);
  return out;
}

} // namespace prism::nsi
