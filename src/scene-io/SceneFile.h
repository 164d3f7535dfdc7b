// Whole files for the scene loaders: the scene itself and the files it names
// (MTL libraries, glTF buffers and images, textures). Only regular files are
// read: a scene naming a FIFO or a device (/dev/stdin, /dev/zero) would
// otherwise block or never end.
#pragma once

#include <string>
#include <vector>

namespace prism::scene_io {

// Reads `path` into `bytes` (sized from the file, then one read: no
// growing copies of a file of gigabytes); false with `error` ("No such
// file or directory", "not a regular file", ...) when it cannot.
bool readSceneFile(
    const std::string &path, std::string &bytes, std::string &error);
bool readSceneFile(const std::string &path,
    std::vector<unsigned char> &bytes,
    std::string &error);

// Whether `path` is a regular file (following symbolic links).
bool isRegularFile(const std::string &path);

// The folder part of `path` with its trailing '/', or "./".
std::string directoryOf(const std::string &path);

} // namespace prism::scene_io
