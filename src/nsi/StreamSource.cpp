#include "StreamSource.h"

#include <zlib.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>

namespace prism::nsi {

bool looksLikeAsciiStream(const std::string &bytes)
{
  for (unsigned char c : bytes) {
    if (std::isspace(c))
      continue;
    return c == '#' || std::isalpha(c);
  }
  return true; // empty or blank: an empty stream
}

bool readStreamText(
    const std::string &fileName, std::string &text, std::string &error)
{
  std::error_code ec;
  if (!std::filesystem::is_regular_file(fileName, ec)) {
    error = ec ? ec.message() : "not a regular file";
    return false;
  }
  // gzread passes plain files through and inflates gzip ones.
  gzFile file = gzopen(fileName.c_str(), "rb");
  if (!file) {
    error = std::strerror(errno);
    return false;
  }
  text.clear();
  char buffer[65536];
  int n;
  while ((n = gzread(file, buffer, sizeof buffer)) > 0)
    text.append(buffer, size_t(n));
  int zlibError = Z_OK;
  const char *message = gzerror(file, &zlibError);
  gzclose(file);
  if (n < 0 || (zlibError != Z_OK && zlibError != Z_STREAM_END)) {
    error = message ? message : "read error";
    return false;
  }
  if (!looksLikeAsciiStream(text)) {
    error = "binary NSI streams are not supported";
    return false;
  }
  return true;
}

} // namespace prism::nsi
