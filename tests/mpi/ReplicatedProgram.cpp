// A single-process ANARI program, unaware of MPI: it renders the whole box
// grid with the path tracer (shadows, accumulation) on the library named by
// ANARI_LIBRARY, and compares the image with the prism device's. ctest runs
// it with ANARI_LIBRARY=prism_mpi and PRISM_MPI_MODE=replicated under
// `mpirun -np 1/2/4`; only rank 0's image is defined, so the other ranks
// check just the tile rows they rendered themselves.
#include "BoxGrid.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace prism::scenes;

namespace {

constexpr uint32_t kWidth = 96;
constexpr uint32_t kHeight = 160; // five rows of 32-pixel tiles
constexpr uint32_t kTileSize = 32;

Image render(const char *libraryName)
{
  ANARILibrary library = anariLoadLibrary(libraryName, nullptr, nullptr);
  if (!library)
    return {};
  ANARIDevice device = anariNewDevice(library, "default");
  ANARIWorld world = newBoxesWorld(device, boxesOf(boxOwners(1, 1), -1));
  addSunlight(device, world);
  const float eye[3] = {3.2f, 2.6f, 4.6f};
  ANARICamera camera = newCamera(device, eye, float(kWidth) / float(kHeight));
  ANARIRenderer renderer = newRenderer(device, "pathtracer");
  ANARIFrame frame = newFrame(device, world, camera, renderer, kWidth, kHeight);
  const bool accumulate = true;
  anariSetParameter(device, frame, "accumulation", ANARI_BOOL, &accumulate);
  anariCommitParameters(device, frame);
  for (int sample = 0; sample < 3; sample++) {
    anariRenderFrame(device, frame);
    anariFrameReady(device, frame, ANARI_WAIT);
  }
  Image image = readFrame(device, frame);
  anariRelease(device, frame);
  anariRelease(device, renderer);
  anariRelease(device, camera);
  anariRelease(device, world);
  anariRelease(device, device);
  anariUnloadLibrary(library);
  return image;
}

int environmentNumber(const char *name, int fallback)
{
  const char *value = std::getenv(name);
  return value ? std::atoi(value) : fallback;
}

bool rowEqual(const Image &a, const Image &b, uint32_t y)
{
  const size_t begin = size_t(y) * kWidth;
  auto same = [&](const std::vector<float> &x,
                  const std::vector<float> &z,
                  size_t components) {
    return std::memcmp(&x[components * begin],
               &z[components * begin],
               components * kWidth * sizeof(float))
           == 0;
  };
  return same(a.color, b.color, 4) && same(a.depth, b.depth, 1)
         && same(a.normal, b.normal, 3) && same(a.albedo, b.albedo, 3);
}

} // namespace

int main()
{
  const Image got = render("environment");
  const Image want = render("prism");
  // Only for choosing what to check: the program itself never calls MPI.
  const int rank = environmentNumber("OMPI_COMM_WORLD_RANK", 0);
  const int ranks = environmentNumber("OMPI_COMM_WORLD_SIZE", 1);
  int failures = 0;
  auto check = [&](bool ok, const char *what) {
    if (!ok) {
      std::fprintf(stderr, "[rank %d] FAILED: %s\n", rank, what);
      failures++;
    }
  };
  const size_t pixels = size_t(kWidth) * kHeight;
  check(want.color.size() == 4 * pixels && want.depth.size() == pixels
            && want.normal.size() == 3 * pixels
            && want.albedo.size() == 3 * pixels,
      "the prism device renders the reference");
  check(got.color.size() == 4 * pixels && got.depth.size() == pixels
            && got.normal.size() == 3 * pixels
            && got.albedo.size() == 3 * pixels,
      "the library under test renders every channel at the frame's size");
  if (failures)
    return 1;
  // The path tracer's image is no flat color: shadows and shading vary.
  size_t distinct = 0;
  for (size_t i = 1; i < pixels; i++)
    distinct += want.color[4 * i] != want.color[4 * (i - 1)];
  if (distinct <= pixels / 4)
    std::fprintf(stderr,
        "%zu of %zu pixels differ from their neighbour\n",
        distinct,
        pixels);
  check(distinct > pixels / 4, "the reference image has structure");

  size_t ownRowsDiffering = 0, otherRowsDiffering = 0;
  for (uint32_t y = 0; y < kHeight; y++) {
    const bool own = int((y / kTileSize) % uint32_t(ranks)) == rank;
    if (rowEqual(got, want, y))
      continue;
    (own ? ownRowsDiffering : otherRowsDiffering)++;
  }
  if (rank == 0) {
    check(ownRowsDiffering + otherRowsDiffering == 0,
        "rank 0's image equals the single-process image bit for bit");
  } else {
    check(ownRowsDiffering == 0,
        "the tile rows this rank rendered equal the single-process image");
    check(otherRowsDiffering > 0,
        "this rank did not render the other ranks' tile rows (work is split)");
  }
  return failures == 0 ? 0 : 1;
}
