// Small NanoVDB grids for the tests, built with NanoVDB's GridBuilder: a
// file as a converter would write it (a vector grid first, then scalars).
#pragma once

#include <nanovdb/util/GridHandle.h>

#include <string>
#include <vector>

namespace prism::render::test_grids {

// A soft ball of density (0 at its rim, 1 at its centre) in an n^3 block of
// voxels of size `voxelSize`, named "density".
nanovdb::GridHandle<> makeDensityBall(int n, double voxelSize);
// A linear ramp 0..1 along x over an n^3 block, named "temperature".
nanovdb::GridHandle<> makeTemperatureRamp(int n);
// A constant Vec3f grid named "velocity" (not a scalar: never rendered).
nanovdb::GridHandle<> makeVelocity(int n);

// A ball of values 0 (rim) to 100 (centre), 20 voxels across, stored as
// `type`: "float", "double", "int32", "Fp8" or "Fp16"; named "ball".
// Without min/max, the grid has bounding boxes but no value statistics.
nanovdb::GridHandle<> makeBall(const std::string &type, bool withMinMax = true);

// velocity, density, temperature: what the CLI tests render.
std::vector<nanovdb::GridHandle<>> makeTestGrids();

} // namespace prism::render::test_grids
