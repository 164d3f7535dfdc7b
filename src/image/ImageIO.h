// Reading and writing images by file extension: .png (8-bit sRGB RGBA),
// .pfm (float RGB) and .exr (float or half RGBA). Failures come back as
// messages, never as exceptions or crashes, whatever the file holds.
#pragma once

#include "Image.h"

#include <string>

namespace prism::image {

// An image, or the reason there is none.
struct ReadResult
{
  Image image;
  std::string error; // empty on success

  bool ok() const
  {
    return error.empty();
  }
};

// Whether an operation succeeded, and why not.
struct Status
{
  std::string error; // empty on success

  bool ok() const
  {
    return error.empty();
  }
};

enum class ExrPixelType { Float, Half };

struct WriteOptions
{
  // Float keeps every value exactly (depth, references); half halves the size.
  ExrPixelType exrPixelType{ExrPixelType::Float};
};

// Reads `path`, choosing the format by its extension (case-insensitive).
// PNG colors are decoded from sRGB to linear; PFM alpha reads as 1.
ReadResult read(const std::string &path);

// Writes `image` to a temporary file beside `path`, then renames it, so no
// half-written file ever appears at `path`. PNG encodes linear colors as
// 8-bit sRGB (clamped to [0, 1]); PFM drops alpha.
Status write(const std::string &path,
    const Image &image,
    const WriteOptions &options = {});

// The sRGB transfer function and its inverse, on values in [0, 1].
float srgbFromLinear(float linear);
float linearFromSrgb(float srgb);

// `image` exactly as writing it to PNG and reading it back would return it.
Image quantizeToSrgb8(const Image &image);

} // namespace prism::image
