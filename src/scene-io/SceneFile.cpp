#include "SceneFile.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

namespace prism::scene_io {

bool isRegularFile(const std::string &path)
{
  struct stat info;
  return ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode);
}

namespace {

template <typename Bytes>
bool readWhole(const std::string &path, Bytes &bytes, std::string &error)
{
  struct stat info;
  if (::stat(path.c_str(), &info) != 0) {
    error = std::strerror(errno);
    return false;
  }
  if (!S_ISREG(info.st_mode)) {
    error = S_ISDIR(info.st_mode) ? "it is a directory" : "not a regular file";
    return false;
  }
  std::unique_ptr<std::FILE, int (*)(std::FILE *)> file(
      std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) {
    error = std::strerror(errno);
    return false;
  }
  // The size stat gave, then whatever a file still being written adds.
  bytes.resize(size_t(info.st_size));
  size_t size = std::fread(bytes.data(), 1, bytes.size(), file.get());
  if (size == bytes.size()) {
    unsigned char buffer[1 << 16];
    for (size_t n; (n = std::fread(buffer, 1, sizeof(buffer), file.get())) > 0;
         size += n)
      bytes.insert(bytes.end(), buffer, buffer + n);
  }
  bytes.resize(size);
  if (std::ferror(file.get())) {
    error = std::strerror(errno);
    return false;
  }
  return true;
}

} // namespace

bool readSceneFile(
    const std::string &path, std::string &bytes, std::string &error)
{
  return readWhole(path, bytes, error);
}

bool readSceneFile(const std::string &path,
    std::vector<unsigned char> &bytes,
    std::string &error)
{
  return readWhole(path, bytes, error);
}

std::string directoryOf(const std::string &path)
{
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string("./")
                                    : path.substr(0, slash + 1);
}

} // namespace prism::scene_io
