// prism-mpi-example: a data-parallel ANARI application in one file. Every
// process of `mpirun` builds its share of a scene (SplitScenes.h), all
// render one frame together through KHR_DATA_PARALLEL_MPI (the prism_mpi
// library), and rank 0 writes the image.
//
//   mpirun -np 4 prism-mpi-example --scene boxes -o boxes.png
//   prism-mpi-example --library prism --scene boxes -o whole.png  # reference
//
// Options: --scene boxes|spheres|volume, --library NAME (default
// prism_mpi), --mode pathtracer|composite|replicated (prism_mpi's device
// parameter; default: pathtracer, composite for the volume, shown by the
// raycast renderer), --renderer SUBTYPE, --size WxH, --spp N (samples
// accumulated), -o FILE (.png, .exr, .pfm).
#include "SplitScenes.h"

#include "BoxGrid.h"
#include "ImageIO.h"

#include <anari/anari.h>
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

using namespace prism;

struct Options
{
  std::string scene{"boxes"};
  std::string library{"prism_mpi"};
  std::string mode;
  std::string renderer;
  uint32_t width{512}, height{512};
  int samples{16};
  std::string output;
};

// Empty on success, else what is wrong.
std::string parse(int argc, char **argv, Options &o)
{
  for (int i = 1; i < argc; i++) {
    const std::string arg = argv[i];
    if (i + 1 >= argc)
      return "expected a value after " + arg;
    const std::string value = argv[++i];
    if (arg == "--scene")
      o.scene = value;
    else if (arg == "--library")
      o.library = value;
    else if (arg == "--mode")
      o.mode = value;
    else if (arg == "--renderer")
      o.renderer = value;
    else if (arg == "--spp")
      o.samples = std::atoi(value.c_str());
    else if (arg == "-o")
      o.output = value;
    else if (arg == "--size") {
      if (std::sscanf(value.c_str(), "%ux%u", &o.width, &o.height) != 2
          || o.width == 0 || o.height == 0)
        return "--size: expected WxH";
    } else {
      return "unknown option " + arg;
    }
  }
  if (o.samples < 1)
    return "--spp: expected a positive number";
  if (o.output.empty())
    o.output = o.scene + ".png";
  return {};
}

void report(const void *,
    ANARIDevice,
    ANARIObject,
    ANARIDataType,
    ANARIStatusSeverity severity,
    ANARIStatusCode,
    const char *message)
{
  if (severity <= ANARI_SEVERITY_WARNING)
    std::fprintf(stderr, "prism-mpi-example: %s\n", message);
}

} // namespace

int main(int argc, char **argv)
{
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  Options options;
  const std::string error = parse(argc, argv, options);
  if (!error.empty()) {
    if (rank == 0)
      std::fprintf(stderr, "prism-mpi-example: %s\n", error.c_str());
    MPI_Finalize();
    return 2;
  }
  // A library that is not data-parallel renders the whole scene alone.
  const bool dataParallel = options.library != "prism";
  const int process = dataParallel ? rank : 0;
  const int processes = dataParallel ? size : 1;

  ANARILibrary library =
      anariLoadLibrary(options.library.c_str(), report, nullptr);
  if (!library) {
    std::fprintf(stderr,
        "prism-mpi-example: cannot load ANARI library '%s'\n",
        options.library.c_str());
    MPI_Finalize();
    return 1;
  }
  ANARIDevice device = anariNewDevice(library, "default");
  const std::string mode = !options.mode.empty()       ? options.mode
                           : options.scene == "volume" ? "composite"
                                                       : "pathtracer";
  if (dataParallel) {
    anariSetParameter(device, device, "mode", ANARI_STRING, mode.c_str());
    const int32_t oneThread = 1; // processes share this machine's cores
    anariSetParameter(device, device, "numThreads", ANARI_INT32, &oneThread);
    anariCommitParameters(device, device);
  }

  mpiexample::SplitScene scene =
      mpiexample::buildSplitScene(device, options.scene, process, processes);
  int status = 0;
  if (!scene.world) {
    if (rank == 0)
      std::fprintf(stderr,
          "prism-mpi-example: unknown scene '%s' (boxes, spheres, volume)\n",
          options.scene.c_str());
    status = 2;
  } else {
    const float aspect = float(options.width) / float(options.height);
    ANARICamera camera = scenes::newCamera(device, scene.eye, aspect);
    ANARIRenderer renderer = scenes::newRenderer(device,
        options.renderer.empty() ? scene.renderer : options.renderer.c_str());
    ANARIFrame frame = scenes::newFrame(
        device, scene.world, camera, renderer, options.width, options.height);
    // --spp N: the image is the average of N accumulated samples.
    const bool accumulate = true;
    anariSetParameter(device, frame, "accumulation", ANARI_BOOL, &accumulate);
    anariCommitParameters(device, frame);
    for (int s = 0; s < options.samples; s++) {
      anariRenderFrame(device, frame); // collective
      anariFrameReady(device, frame, ANARI_WAIT);
    }
    if (rank == 0 || !dataParallel) {
      const scenes::Image pixels = scenes::readFrame(device, frame);
      image::Image out(pixels.width, pixels.height);
      for (size_t i = 0; i < out.pixels.size(); i++)
        out.pixels[i] = {pixels.color[4 * i],
            pixels.color[4 * i + 1],
            pixels.color[4 * i + 2],
            pixels.color[4 * i + 3]};
      const image::Status written = image::write(options.output, out);
      if (written.ok()) {
        std::printf("wrote %s (%ux%u, %d processes)\n",
            options.output.c_str(),
            out.width,
            out.height,
            processes);
      } else {
        std::fprintf(stderr, "prism-mpi-example: %s\n", written.error.c_str());
        status = 1;
      }
    }
    anariRelease(device, frame);
    anariRelease(device, renderer);
    anariRelease(device, camera);
    anariRelease(device, scene.world);
  }
  anariRelease(device, device); // collective for prism_mpi
  anariUnloadLibrary(library);
  MPI_Finalize();
  return status;
}
