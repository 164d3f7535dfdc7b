#include "TextureFile.h"

#include "ImageIO.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>

// A private stb_image: static linkage, so it cannot clash with the copy
// compiled inside prism_image (or any other in the process).
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_FAILURE_USERMSG
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace prism::scene_io {
namespace {

// The same cap as prism_image: no texture needs more, and a corrupt header
// must not make us allocate gigabytes.
constexpr uint64_t kMaxPixels = 64ull << 20;

std::string lowerExtension(const std::string &path)
{
  const size_t dot = path.find_last_of('.');
  const size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return {};
  std::string extension = path.substr(dot);
  for (char &c : extension)
    c = char(std::tolower((unsigned char)c));
  return extension;
}

} // namespace

TextureResult readTexture(const std::string &path)
{
  TextureResult result;
  // A FIFO or device named as a texture would block or never end.
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (std::filesystem::exists(status)
      && !std::filesystem::is_regular_file(status)) {
    result.error = "'" + path + "': not a regular file";
    return result;
  }
  const std::string extension = lowerExtension(path);
  if (extension == ".png" || extension == ".exr" || extension == ".pfm") {
    image::ReadResult read = image::read(path);
    if (!read.ok())
      result.error = read.error;
    else
      result.image = std::move(read.image);
    return result;
  }

  int width = 0, height = 0, components = 0;
  if (!stbi_info(path.c_str(), &width, &height, &components)) {
    result.error = "'" + path + "': " + stbi_failure_reason();
    return result;
  }
  if (width <= 0 || height <= 0
      || uint64_t(width) * uint64_t(height) > kMaxPixels) {
    result.error = "'" + path + "': image too large";
    return result;
  }
  const bool hdr = stbi_is_hdr(path.c_str()) != 0;
  void *pixels =
      hdr ? (void *)stbi_loadf(path.c_str(), &width, &height, &components, 4)
          : (void *)stbi_load(path.c_str(), &width, &height, &components, 4);
  if (!pixels) {
    result.error = "'" + path + "': " + stbi_failure_reason();
    return result;
  }
  image::Image &out = result.image;
  out = image::Image(uint32_t(width), uint32_t(height));
  for (uint32_t y = 0; y < out.height; y++) {
    // Files store the top row first; Image rows count from the bottom.
    const size_t row = size_t(out.height - 1 - y) * out.width;
    for (uint32_t x = 0; x < out.width; x++) {
      image::Rgba &p = out.at(x, y);
      const size_t i = (row + x) * 4;
      if (hdr) {
        const float *f = (const float *)pixels + i;
        p = {f[0], f[1], f[2], f[3]};
      } else {
        const unsigned char *b = (const unsigned char *)pixels + i;
        p = {image::linearFromSrgb(b[0] / 255.f),
            image::linearFromSrgb(b[1] / 255.f),
            image::linearFromSrgb(b[2] / 255.f),
            b[3] / 255.f};
      }
    }
  }
  stbi_image_free(pixels);
  return result;
}

} // namespace prism::scene_io
