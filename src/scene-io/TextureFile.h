// Texture images from files for the OBJ loader: PNG, EXR and PFM through
// prism_image (checked before decoding), JPEG, TGA, BMP and the other formats
// stb_image knows through a private copy of stb compiled in TextureFile.cpp.
#pragma once

#include "Image.h"

#include <string>

namespace prism::scene_io {

struct TextureResult
{
  image::Image image; // linear RGBA, row 0 at the bottom
  std::string error;  // empty on success

  bool ok() const
  {
    return error.empty();
  }
};

TextureResult readTexture(const std::string &path);

} // namespace prism::scene_io
