#include "HdriHemispheres.h"

#include "Sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prism::light {
namespace {

constexpr size_t kMaxCellsX = 32, kMaxCellsY = 16;
// The share of a facing receiver's samples that follow the image alone.
constexpr float kImageShare = 0.1f;
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;
constexpr float kLargestFloat = std::numeric_limits<float>::max();

float3 axisDirection(int axis)
{
  float3 d{0.f, 0.f, 0.f};
  d[axis / 2] = axis % 2 == 0 ? 1.f : -1.f;
  return d;
}

// The direction of image coordinates (s, t) in the light's frame.
float3 directionAt(float s, float t)
{
  const float theta = kPi * t, phi = 2.f * kPi * (s - 0.5f);
  return {std::sin(theta) * std::cos(phi),
      std::sin(theta) * std::sin(phi),
      std::cos(theta)};
}

// Where `count` cells start over `size` texels (count + 1 entries), and
// the cell of every texel.
void cut(size_t size,
    size_t count,
    std::vector<size_t> &start,
    std::vector<uint32_t> &cellOf)
{
  start.resize(count + 1);
  for (size_t c = 0; c <= count; c++)
    start[c] = c * size / count;
  cellOf.resize(size);
  for (size_t c = 0; c < count; c++)
    for (size_t i = start[c]; i < start[c + 1]; i++)
      cellOf[i] = uint32_t(c);
}

} // namespace

HdriHemispheres::HdriHemispheres(
    const std::vector<float> &weights, size_t width, size_t height)
    : m_width(width), m_height(height)
{
  if (width == 0 || height == 0)
    return;
  m_cellsX = std::min(width, kMaxCellsX);
  m_cellsY = std::min(height, kMaxCellsY);
  cut(width, m_cellsX, m_columnStart, m_cellOfColumn);
  cut(height, m_cellsY, m_rowStart, m_cellOfRow);
  m_columnSums.assign(m_cellsX, std::vector<double>(height + 1, 0.0));
  for (size_t cx = 0; cx < m_cellsX; cx++) {
    std::vector<double> &sums = m_columnSums[cx];
    for (size_t j = 0; j < height; j++) {
      double row = 0.0;
      for (size_t i = m_columnStart[cx]; i < m_columnStart[cx + 1]; i++)
        row += usableWeight(weights[i + j * width]); // as the image counts
      sums[j + 1] = sums[j] + row;
    }
  }
  const size_t cells = m_cellsX * m_cellsY;
  std::vector<double> cellWeight(cells);
  double total = 0.0;
  for (size_t cy = 0; cy < m_cellsY; cy++) {
    for (size_t cx = 0; cx < m_cellsX; cx++) {
      const std::vector<double> &sums = m_columnSums[cx];
      cellWeight[cx + cy * m_cellsX] =
          sums[m_rowStart[cy + 1]] - sums[m_rowStart[cy]];
      total += cellWeight[cx + cy * m_cellsX];
    }
  }
  for (int axis = 0; axis < kAxes; axis++) {
    const float3 towards = axisDirection(axis);
    std::vector<float> cosine(cells), axisWeight(cells);
    double axisTotal = 0.0;
    for (size_t cy = 0; cy < m_cellsY; cy++) {
      for (size_t cx = 0; cx < m_cellsX; cx++) {
        const float best = bestCosine(cx, cy, towards);
        const size_t c = cx + cy * m_cellsX;
        cosine[c] = best;
        axisWeight[c] = float(cellWeight[c] * double(best));
        axisTotal += double(axisWeight[c]);
      }
    }
    m_usable[axis] = total > 0.0 && axisTotal > 0.0;
    m_ratio[axis].assign(cells, 0.f);
    if (!m_usable[axis])
      continue;
    m_axisCells[axis] = Distribution2D(axisWeight.data(), m_cellsX, m_cellsY);
    // Axis k picks cell C with W(C) cos(C) / sum_k and a texel in it with
    // w / W(C); the image picks it with w / total.
    for (size_t c = 0; c < cells; c++)
      m_ratio[axis][c] = float(double(cosine[c]) * total / axisTotal);
  }
}

float HdriHemispheres::bestCosine(
    size_t cx, size_t cy, const float3 &towards) const
{
  // At the cell's corners, edges' midpoints and centre, at least 0: a
  // cell only partly above the axis' horizon keeps weight.
  float best = 0.f;
  for (int b = 0; b <= 2; b++) {
    const float t = (float(m_rowStart[cy]) * float(2 - b)
                        + float(m_rowStart[cy + 1]) * float(b))
                    / (2.f * float(m_height));
    for (int a = 0; a <= 2; a++) {
      const float s = (float(m_columnStart[cx]) * float(2 - a)
                          + float(m_columnStart[cx + 1]) * float(a))
                      / (2.f * float(m_width));
      best = std::max(best, dot(directionAt(s, t), towards));
    }
  }
  return best;
}

HdriHemispheres::Mixture HdriHemispheres::mixture(const float3 &normal) const
{
  Mixture m = kEverySide;
  const float length2 = lengthSquared(normal);
  if (empty() || !(length2 > 0.f && length2 <= kLargestFloat))
    return m;
  // Squared components over the squared length: shares that sum to one
  // whatever the normal's rounding.
  const float scale = (1.f - kImageShare) / length2;
  float facing = 0.f;
  for (int k = 0; k < 3; k++) {
    const int axis = 2 * k + (normal[k] < 0.f ? 1 : 0);
    if (m_usable[axis]) {
      m[1 + axis] = scale * normal[k] * normal[k];
      facing += m[1 + axis];
    }
  }
  m[0] = 1.f - facing;
  return m;
}

int HdriHemispheres::component(const Mixture &mixture, float &u)
{
  if (u < mixture[0]) {
    u = std::clamp(u / mixture[0], 0.f, kOneMinusEpsilon);
    return -1;
  }
  // The axis whose stretch after the image's holds u; the last axis with
  // a share also takes what rounding leaves above the sum.
  int chosen = -1;
  float start = mixture[0], chosenStart = 0.f;
  for (int axis = 0; axis < kAxes; axis++) {
    const float share = mixture[size_t(1 + axis)];
    if (!(share > 0.f))
      continue;
    chosen = axis;
    chosenStart = start;
    if (u < start + share)
      break;
    start += share;
  }
  if (chosen < 0) // no axis: rounding put u past an image share below 1
    return -1;
  const float share = mixture[size_t(1 + chosen)];
  u = std::clamp((u - chosenStart) / share, 0.f, kOneMinusEpsilon);
  return chosen;
}

float HdriHemispheres::factor(const Mixture &mixture, size_t i, size_t j) const
{
  if (empty() || mixture[0] >= 1.f)
    return 1.f;
  const size_t c = cellOf(std::min(i, m_width - 1), std::min(j, m_height - 1));
  float f = mixture[0];
  for (int axis = 0; axis < kAxes; axis++)
    f += mixture[1 + axis] * m_ratio[axis][c];
  return f;
}

void HdriHemispheres::sample(const Distribution2D &image,
    int axis,
    float2 &u,
    size_t &i,
    size_t &j) const
{
  float pdf = 0.f;
  const float2 p = m_axisCells[axis].sample(u, pdf);
  const float x = p.x * float(m_cellsX), y = p.y * float(m_cellsY);
  const size_t cx = std::min(size_t(x), m_cellsX - 1);
  const size_t cy = std::min(size_t(y), m_cellsY - 1);
  u = {std::clamp(x - float(cx), 0.f, kOneMinusEpsilon),
      std::clamp(y - float(cy), 0.f, kOneMinusEpsilon)};
  // A row of the cell by its weight within the cell's columns.
  const std::vector<double> &sums = m_columnSums[cx];
  const size_t top = m_rowStart[cy], bottom = m_rowStart[cy + 1];
  const double target = sums[top] + double(u.y) * (sums[bottom] - sums[top]);
  const auto above = std::upper_bound(sums.begin() + ptrdiff_t(top) + 1,
      sums.begin() + ptrdiff_t(bottom),
      target);
  j = size_t(above - sums.begin()) - 1;
  const double rowWeight = sums[j + 1] - sums[j];
  u.y = rowWeight > 0.0 ? std::clamp(
            float((target - sums[j]) / rowWeight), 0.f, kOneMinusEpsilon)
                        : 0.5f;
  // A texel of that row within the cell, as the image's row chooses.
  i = image.row(j).sampleBetween(u.x, m_columnStart[cx], m_columnStart[cx + 1]);
}

} // namespace prism::light
