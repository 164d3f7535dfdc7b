#include "NanoVdbTestGrids.h"

#include <nanovdb/util/GridBuilder.h>

#include <algorithm>
#include <cmath>

namespace prism::render::test_grids {

nanovdb::GridHandle<> makeDensityBall(int n, double voxelSize)
{
  nanovdb::GridBuilder<float> builder(0.f, nanovdb::GridClass::FogVolume);
  auto voxels = builder.getAccessor();
  const float centre = 0.5f * float(n - 1), radius = 0.5f * float(n);
  for (int k = 0; k < n; k++)
    for (int j = 0; j < n; j++)
      for (int i = 0; i < n; i++) {
        const float dx = float(i) - centre, dy = float(j) - centre,
                    dz = float(k) - centre;
        const float r = std::sqrt(dx * dx + dy * dy + dz * dz) / radius;
        if (r < 1.f)
          voxels.setValue(nanovdb::Coord(i, j, k), 1.f - r * r);
      }
  return builder.getHandle<>(voxelSize, nanovdb::Vec3d(0.0), "density");
}

nanovdb::GridHandle<> makeTemperatureRamp(int n)
{
  nanovdb::GridBuilder<float> builder(0.f);
  auto voxels = builder.getAccessor();
  for (int k = 0; k < n; k++)
    for (int j = 0; j < n; j++)
      for (int i = 0; i < n; i++)
        voxels.setValue(nanovdb::Coord(i, j, k),
            0.01f + 0.99f * float(i) / float(std::max(n - 1, 1)));
  return builder.getHandle<>(1.0, nanovdb::Vec3d(0.0), "temperature");
}

nanovdb::GridHandle<> makeVelocity(int n)
{
  nanovdb::GridBuilder<nanovdb::Vec3f> builder(nanovdb::Vec3f(0.f));
  auto voxels = builder.getAccessor();
  for (int k = 0; k < n; k++)
    for (int j = 0; j < n; j++)
      for (int i = 0; i < n; i++)
        voxels.setValue(nanovdb::Coord(i, j, k), nanovdb::Vec3f(1.f, 0.f, 0.f));
  return builder.getHandle<>(1.0, nanovdb::Vec3d(0.0), "velocity");
}

namespace {

template <typename ValueT, typename BuildT>
nanovdb::GridHandle<> makeBallOf(bool withMinMax)
{
  nanovdb::GridBuilder<ValueT, BuildT> builder(ValueT(0));
  if (!withMinMax)
    builder.setStats(nanovdb::StatsMode::BBox);
  auto voxels = builder.getAccessor();
  for (int k = 0; k < 20; k++)
    for (int j = 0; j < 20; j++)
      for (int i = 0; i < 20; i++) {
        const float r =
            std::sqrt(float((i - 10) * (i - 10) + (j - 10) * (j - 10)
                            + (k - 10) * (k - 10)))
            / 10.f;
        if (r < 1.f)
          voxels.setValue(
              nanovdb::Coord(i, j, k), ValueT(std::lround(100.f * (1.f - r))));
      }
  return builder.template getHandle<>(1.0, nanovdb::Vec3d(0.0), "ball");
}

} // namespace

nanovdb::GridHandle<> makeBall(const std::string &type, bool withMinMax)
{
  if (type == "double")
    return makeBallOf<double, double>(withMinMax);
  if (type == "int32")
    return makeBallOf<int32_t, int32_t>(withMinMax);
  if (type == "Fp8")
    return makeBallOf<float, nanovdb::Fp8>(withMinMax);
  if (type == "Fp16")
    return makeBallOf<float, nanovdb::Fp16>(withMinMax);
  return makeBallOf<float, float>(withMinMax);
}

std::vector<nanovdb::GridHandle<>> makeTestGrids()
{
  std::vector<nanovdb::GridHandle<>> grids;
  grids.push_back(makeVelocity(4));
  grids.push_back(makeDensityBall(24, 0.1));
  grids.push_back(makeTemperatureRamp(16));
  return grids;
}

} // namespace prism::render::test_grids
