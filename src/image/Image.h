// A float RGBA image in memory, with ANARI's lower-left origin: row 0 is the
// BOTTOM row. File readers and writers flip rows as their formats require.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace prism::image {

// One pixel: linear color and alpha, laid out like ANARI_FLOAT32_VEC4.
struct Rgba
{
  float r, g, b, a;

  float &operator[](int i)
  {
    return (&r)[i];
  }
  float operator[](int i) const
  {
    return (&r)[i];
  }
  bool operator==(const Rgba &) const = default;
};
static_assert(
    sizeof(Rgba) == 4 * sizeof(float), "Rgba must match FLOAT32_VEC4");

struct Image
{
  uint32_t width{0};
  uint32_t height{0};
  std::vector<Rgba> pixels; // row-major, row 0 at the bottom

  Image() = default;
  Image(uint32_t w, uint32_t h, Rgba fill = {0.f, 0.f, 0.f, 1.f})
      : width(w), height(h), pixels(size_t(w) * h, fill)
  {}

  bool empty() const
  {
    return pixels.empty();
  }
  // The pixel in column x of row y, counting rows from the bottom.
  Rgba &at(uint32_t x, uint32_t y)
  {
    return pixels[size_t(y) * width + x];
  }
  const Rgba &at(uint32_t x, uint32_t y) const
  {
    return pixels[size_t(y) * width + x];
  }
};

} // namespace prism::image
