// The background image (KHR_RENDERER_BACKGROUND_IMAGE): an ARRAY2D stretched
// over the whole frame with bilinear filtering, texel row 0 at the bottom.
#include "RenderTest.h"

#include <algorithm>

namespace {

using BackgroundImage = RenderTest;

TEST_F(BackgroundImage, Default)
{
  // Red grows to the right, green upwards, and one blue texel marks the top
  // left corner, so a flip, transpose or shift shows in the image.
  constexpr int kWidth = 4, kHeight = 3;
  float texels[kHeight][kWidth][4];
  for (int y = 0; y < kHeight; y++) {
    for (int x = 0; x < kWidth; x++) {
      const bool corner = x == 0 && y == kHeight - 1;
      const float texel[4] = {x / 3.f, y / 2.f, corner ? 1.f : 0.1f, 1.f};
      std::copy(texel, texel + 4, texels[y][x]);
    }
  }
  ANARIArray2D image = newArray2D(ANARI_FLOAT32_VEC4, texels, kWidth, kHeight);
  ANARIRenderer renderer = newRenderer();
  anariSetParameter(device(), renderer, "background", ANARI_ARRAY2D, &image);
  anariCommitParameters(device(), renderer);
  ANARICamera camera =
      newPerspectiveCamera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 64.f / 48.f);
  renderAndCompare(newWorld(), camera, renderer, 64, 48);
}

} // namespace
