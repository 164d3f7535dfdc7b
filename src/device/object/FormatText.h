// printf-style text for status messages, of any length.
#pragma once

#include <cstdarg>
#include <string>

namespace prism {

std::string formatText(const char *pattern, ...)
    __attribute__((format(printf, 1, 2)));
std::string formatTextV(const char *pattern, va_list args);

} // namespace prism
