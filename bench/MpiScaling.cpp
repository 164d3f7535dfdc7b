// prism-bench-mpi: frame times of the prism_mpi device under mpirun, for
// strong scaling (one box grid split over the processes) and weak scaling
// (each process adds a grid of its own), in pathtracer, composite or
// replicated mode. The path tracer's boxes are lit by a directional light,
// the same on every process. Prints one line on rank 0; never part of the
// test suite.
//
//   mpirun -np N prism-bench-mpi [--mode pathtracer|composite|replicated]
//       [--scaling strong|weak] [--renderer raycast|pathtracer]
//       [--size PIXELS] [--side BOXES] [--frames N] [--threads N]
#include "BoxGrid.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace prism::scenes;

namespace {

struct Options
{
  std::string mode = "composite";
  std::string scaling = "strong";
  std::string renderer = "raycast";
  uint32_t size = 512;
  int side = 8;
  int frames = 5;
  int threads = 0; // per process; 0: every hardware thread
};

bool parse(int argc, char **argv, Options &o)
{
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--mode")
      o.mode = value;
    else if (key == "--scaling")
      o.scaling = value;
    else if (key == "--renderer")
      o.renderer = value;
    else if (key == "--size")
      o.size = uint32_t(std::max(1, std::atoi(value.c_str())));
    else if (key == "--side")
      o.side = std::max(1, std::atoi(value.c_str()));
    else if (key == "--threads")
      o.threads = std::max(0, std::atoi(value.c_str()));
    else if (key == "--frames")
      o.frames = std::max(1, std::atoi(value.c_str()));
    else
      return false;
  }
  return (argc % 2) == 1;
}

} // namespace

int main(int argc, char **argv)
{
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  Options o;
  if (!parse(argc, argv, o)) {
    if (rank == 0)
      std::fprintf(
          stderr, "usage: see the comment atop bench/MpiScaling.cpp\n");
    MPI_Finalize();
    return 2;
  }

  ANARILibrary library = anariLoadLibrary("prism_mpi", nullptr, nullptr);
  ANARIDevice device = library ? anariNewDevice(library, "default") : nullptr;
  if (!device) {
    std::fprintf(stderr, "[rank %d] cannot load prism_mpi\n", rank);
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  anariSetParameter(device, device, "mode", ANARI_STRING, o.mode.c_str());
  const int32_t threads = o.threads;
  anariSetParameter(device, device, "numThreads", ANARI_INT32, &threads);

  // Strong: one grid, split over the processes (composite, pathtracer) or
  // whole on every one (replicated). Weak (where each process's data is its
  // own, not replicated): a whole grid per process, side by side along x.
  const bool weak = o.scaling == "weak";
  const bool replicated = o.mode == "replicated";
  if (weak && replicated) {
    if (rank == 0)
      std::fprintf(stderr, "weak scaling does not apply to replicated mode\n");
    MPI_Finalize();
    return 2;
  }
  const std::vector<int> owners = boxOwners(ranks, 1, o.side);
  const int grids = weak ? ranks : 1;
  const std::vector<int> boxes =
      weak || replicated ? boxesOf(owners, -1) : boxesOf(owners, rank);
  const float offset =
      weak ? float(rank * o.side) - float((grids - 1) * o.side) / 2.f : 0.f;
  ANARIWorld world = newBoxesWorld(device, boxes, o.side, offset);
  if (o.renderer == "pathtracer")
    addSunlight(device, world);
  MPI_Comm comm = MPI_COMM_WORLD;
  anariSetParameter(
      device, world, "mpiCommunicator", ANARI_VOID_POINTER, &comm);
  anariCommitParameters(device, world);

  const float extent = float(o.side * grids);
  const float eye[3] = {0.9f * extent, 0.7f * extent, 1.3f * extent};
  ANARICamera camera = newCamera(device, eye, 1.f);
  ANARIRenderer renderer = newRenderer(device, o.renderer.c_str());
  ANARIFrame frame = newFrame(device, world, camera, renderer, o.size, o.size);
  anariSetParameter(
      device, frame, "mpiCommunicator", ANARI_VOID_POINTER, &comm);
  anariCommitParameters(device, frame);

  std::vector<double> seconds;
  uint64_t bytes = 0;
  for (int f = 0; f <= o.frames; f++) {
    MPI_Barrier(MPI_COMM_WORLD);
    const double start = MPI_Wtime();
    anariRenderFrame(device, frame);
    anariFrameReady(device, frame, ANARI_WAIT);
    const double took = MPI_Wtime() - start;
    if (f > 0) // the first frame builds the BVHs
      seconds.push_back(took);
    anariGetProperty(device,
        frame,
        "mpiBytesSent",
        ANARI_UINT64,
        &bytes,
        sizeof(bytes),
        ANARI_WAIT);
  }
  std::sort(seconds.begin(), seconds.end());
  double slowest = seconds[seconds.size() / 2];
  MPI_Allreduce(MPI_IN_PLACE, &slowest, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  uint64_t totalBytes = 0;
  MPI_Reduce(&bytes, &totalBytes, 1, MPI_UINT64_T, MPI_SUM, 0, MPI_COMM_WORLD);
  if (rank == 0) {
    std::printf(
        "mode %s scaling %s renderer %s ranks %d threads/rank %s size %u "
        "boxes/rank %d: "
        "median frame %.2f ms, %.2f MB sent per frame (all ranks)\n",
        o.mode.c_str(),
        o.scaling.c_str(),
        o.renderer.c_str(),
        ranks,
        o.threads > 0 ? std::to_string(o.threads).c_str() : "all",
        o.size,
        weak || replicated ? o.side * o.side * o.side
                           : o.side * o.side * o.side / ranks,
        slowest * 1e3,
        double(totalBytes) / 1e6);
  }
  anariRelease(device, frame);
  anariRelease(device, renderer);
  anariRelease(device, camera);
  anariRelease(device, world);
  anariRelease(device, device);
  anariUnloadLibrary(library);
  MPI_Finalize();
  return 0;
}
