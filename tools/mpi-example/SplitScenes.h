// Scenes dealt out over the processes of an MPI communicator, the way a
// data-parallel application holds its data: each process builds only its
// share, through the public ANARI API, and every process the same lights.
#pragma once

#include <anari/anari.h>

#include <string>

namespace prism::mpiexample {

struct SplitScene
{
  ANARIWorld world{nullptr}; // committed; the caller releases it
  // A camera position looking at the origin, and the suggested renderer.
  float eye[3]{0.f, 0.f, 10.f};
  const char *renderer{"pathtracer"};
};

// `name`: "boxes" (the data-parallel paper's 4x4x4 boxes, dealt out at
// random), "spheres" (300 spheres on a floor, sphere i on process
// i % processes, the floor on process 0) or "volume" (a 64^3 field of soft
// blobs, bricked into slabs along z, one per process, sharing their
// boundary voxels so interpolation is seamless). Returns a null world for
// other names.
SplitScene buildSplitScene(
    ANARIDevice device, const std::string &name, int process, int processes);

} // namespace prism::mpiexample
