#include "Guides.h"

namespace prism::denoising {

namespace {

// Averaged normals shorter than this are "no surface" (background).
constexpr float kMinNormalLength = 1e-3f;

constexpr float kInfinity = std::numeric_limits<float>::infinity();

bool isFinite(float3 v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Smaller one-sided difference: across a depth edge the change is larger.
float depthSlope(float here, float before, float after)
{
  const bool hasBefore = std::isfinite(before);
  const bool hasAfter = std::isfinite(after);
  if (hasBefore && hasAfter) {
    const float backward = here - before, forward = after - here;
    return std::abs(backward) <= std::abs(forward) ? backward : forward;
  }
  if (hasBefore)
    return here - before;
  if (hasAfter)
    return after - here;
  return 0.f;
}

} // namespace

void buildGuides(const DenoiseInputs &in, Guide *guides)
{
  const PixelGrid grid{int(in.width), int(in.height)};
  forEachRow(grid, [&](int y) {
    for (int x = 0; x < grid.width; x++) {
      const size_t i = grid.index(x, y);
      Guide &guide = guides[i];
      guide.normal = {0.f, 0.f, 0.f};
      guide.kind = 0;
      if (in.normal && isFinite(in.normal[i])) {
        const float normalLength = length(in.normal[i]);
        if (normalLength >= kMinNormalLength) {
          guide.normal = in.normal[i] / normalLength;
          guide.kind |= Guide::kHasNormal;
        }
      }
      // Without depth every pixel is a hit at 0, so the depth test passes.
      guide.depth = 0.f;
      if (in.depth)
        guide.depth = std::isfinite(in.depth[i]) ? in.depth[i] : kInfinity;
      if (std::isfinite(guide.depth))
        guide.kind |= Guide::kHit;
    }
  });

  // Screen-space depth slopes, once the depths of all rows are known.
  forEachRow(grid, [&](int y) {
    for (int x = 0; x < grid.width; x++) {
      Guide &guide = guides[grid.index(x, y)];
      if (!std::isfinite(guide.depth)) {
        guide.depthSlope = {0.f, 0.f};
        continue;
      }
      const auto depthAt = [&](int qx, int qy) {
        return grid.contains(qx, qy) ? guides[grid.index(qx, qy)].depth
                                     : kInfinity;
      };
      guide.depthSlope = {
          depthSlope(guide.depth, depthAt(x - 1, y), depthAt(x + 1, y)),
          depthSlope(guide.depth, depthAt(x, y - 1), depthAt(x, y + 1))};
    }
  });
}

} // namespace prism::denoising
