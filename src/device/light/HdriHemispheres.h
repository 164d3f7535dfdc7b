// The hdri light's sampling towards one side: a receiver takes light only
// from the hemisphere its normal faces, and an image sampled by luminance
// alone spends about half its samples below that horizon (55 % on the
// sky-lit benchmark scene). The image is cut into cells (up to 32 x 16);
// for each of the six axes of the light's frame, cells are weighed by
// their luminance times the best cosine towards the axis. A receiver
// samples a mixture: a tenth by luminance alone (so every direction the
// image lights keeps a share, whatever the cells' cosines say, and no
// sample weighs more than ten times what it would by luminance alone),
// the rest split between the three axes on its side by its normal's
// squared components. Within a cell every component chooses texels as the
// image's own distribution does, so the mixture's density is that
// distribution's times a factor per cell: density() stays one lookup more.
#pragma once

#include "../math/Vec.h"
#include "Distribution2D.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace prism::light {

class HdriHemispheres
{
 public:
  static constexpr int kAxes = 6; // +x, -x, +y, -y, +z, -z

  // How much of a receiver's samples each component takes: [0] the
  // image's own distribution, [1 + k] axis k's.
  using Mixture = std::array<float, 1 + kAxes>;
  // A receiver without a side: the image's distribution alone.
  static constexpr Mixture kEverySide{1.f, 0.f, 0.f, 0.f, 0.f, 0.f, 0.f};

  HdriHemispheres() = default;
  // Over the image's per-texel sampling weights (width x height, the
  // ones `image` was built from), for directions of (s, t) in the light's
  // frame: theta = pi t from +z, phi = 2 pi (s - 0.5) from +x towards +y.
  HdriHemispheres(
      const std::vector<float> &weights, size_t width, size_t height);

  bool empty() const
  {
    return m_cellsX == 0;
  }
  // The components for a receiver facing `normal` (in the light's frame;
  // zero or not finite: kEverySide).
  Mixture mixture(const float3 &normal) const;
  // The component `u` chooses (-1 the image's, else an axis), leaving in
  // `u` a fresh uniform number: its place within the component's share.
  static int component(const Mixture &mixture, float &u);
  // The mixture's density over the image's, in texel (i, j).
  float factor(const Mixture &mixture, size_t i, size_t j) const;
  // A texel chosen by axis `axis`'s component with `u`, and in `u` what is
  // left of it: uniform numbers for the point within the texel. `image`
  // is the distribution the weights built.
  void sample(const Distribution2D &image,
      int axis,
      float2 &u,
      size_t &i,
      size_t &j) const;

 private:
  // The largest cosine towards `towards` over cell (cx, cy).
  float bestCosine(size_t cx, size_t cy, const float3 &towards) const;
  size_t cellOf(size_t i, size_t j) const
  {
    return m_cellOfColumn[i] + m_cellOfRow[j] * m_cellsX;
  }

  size_t m_width{0}, m_height{0};
  size_t m_cellsX{0}, m_cellsY{0};
  std::vector<size_t> m_columnStart, m_rowStart; // cells' first texels, + end
  std::vector<uint32_t> m_cellOfColumn, m_cellOfRow;
  // Per column of cells, the running sum of its texels' weights down the
  // rows (height + 1 entries each): a cell's rows are chosen from it.
  std::vector<std::vector<double>> m_columnSums;
  std::array<Distribution2D, kAxes> m_axisCells; // cells by weight x cosine
  // Per axis and cell: its cosine over the axis' mean, the ratio of the
  // axis component's density to the image's there (0 where it has none).
  std::array<std::vector<float>, kAxes> m_ratio;
  std::array<bool, kAxes> m_usable{};
};

} // namespace prism::light
