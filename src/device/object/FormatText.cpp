#include "FormatText.h"

#include <cstdio>

namespace prism {

std::string formatTextV(const char *pattern, va_list args)
{
  va_list measure;
  va_copy(measure, args);
  const int length = std::vsnprintf(nullptr, 0, pattern, measure);
  va_end(measure);
  if (length <= 0)
    return {};
  std::string text(size_t(length), '\0');
  std::vsnprintf(text.data(), text.size() + 1, pattern, args);
  return text;
}

std::string formatText(const char *pattern, ...)
{
  va_list args;
  va_start(args, pattern);
  std::string text = formatTextV(pattern, args);
  va_end(args);
  return text;
}

} // namespace prism
