// Writes the NanoVDB files the CLI tests render into the folder given:
// grids.nvdb (velocity, density, temperature), grids-zip.nvdb (the same,
// ZIP-compressed), ball-<type>.nvdb (one ball as float, double, int32,
// Fp8, Fp16; and as float without min/max statistics), small-zip.nvdb (a
// 4^3 ball, ZIP: fuzz_loader's seed), blosc.nvdb (labelled BLOSC), and
// broken copies: cut in a grid, cut in the header, a name size past the
// end of the file, a file of something else, and a density grid whose
// tree points outside it.
#include "NanoVdbTestGrids.h"

#define NANOVDB_USE_ZIP
#include <nanovdb/util/IO.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace {

std::string readAll(const std::string &path)
{
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void writeAll(const std::string &path, const std::string &bytes)
{
  std::ofstream(path, std::ios::binary).write(bytes.data(), bytes.size());
}

} // namespace

int main(int argc, char **argv)
{
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_nanovdb_files FOLDER\n");
    return 2;
  }
  const std::string folder = std::string(argv[1]) + "/";
  try {
    std::filesystem::create_directories(argv[1]);
    const auto grids = prism::render::test_grids::makeTestGrids();
    nanovdb::io::writeGrids(folder + "grids.nvdb", grids);
    nanovdb::io::writeGrids(
        folder + "grids-zip.nvdb", grids, nanovdb::io::Codec::ZIP);
    for (const char *type : {"float", "double", "int32", "Fp8", "Fp16"})
      nanovdb::io::writeGrid(folder + "ball-" + type + ".nvdb",
          prism::render::test_grids::makeBall(type));
    nanovdb::io::writeGrid(folder + "ball-no-min-max.nvdb",
        prism::render::test_grids::makeBall("float", false));
    // Small enough (ZIP) for fuzz_loader's seed corpus.
    nanovdb::io::writeGrid(folder + "small-zip.nvdb",
        prism::render::test_grids::makeDensityBall(4, 0.5),
        nanovdb::io::Codec::ZIP);
  } catch (const std::exception &e) {
    std::fprintf(stderr, "write_nanovdb_files: %s\n", e.what());
    return 1;
  }
  // The ZIP file labelled BLOSC (the segment header's codec, bytes 14-15):
  // one chunk under 1 GiB is laid out alike, so only the codec is refused.
  std::string blosc = readAll(folder + "grids-zip.nvdb");
  const uint16_t bloscCodec = uint16_t(nanovdb::io::Codec::BLOSC);
  std::memcpy(blosc.data() + 14, &bloscCodec, sizeof(bloscCodec));
  writeAll(folder + "blosc.nvdb", blosc);
  const std::string bytes = readAll(folder + "grids.nvdb");
  writeAll(folder + "truncated.nvdb", bytes.substr(0, bytes.size() / 2));
  writeAll(folder + "truncated-header.nvdb", bytes.substr(0, 100));
  // The first grid's nameSize (at byte 16 + 136 of its metadata) made huge.
  std::string hugeName = bytes;
  const uint32_t huge = 0xfffffff0u;
  std::memcpy(hugeName.data() + 16 + 136, &huge, sizeof(huge));
  writeAll(folder + "huge-name.nvdb", hugeName);
  writeAll(folder + "not-nanovdb.nvdb", std::string(64, 'x'));
  // The density grid's lower-node offset (its tree's mNodeOffset[1]) far
  // past the grid: the table of contents is fine, the tree is not.
  std::string corruptTree = bytes;
  uint64_t densityStart = 16;
  uint64_t firstGridBytes = 0;
  std::memcpy(&firstGridBytes, bytes.data() + 16 + 8, sizeof(uint64_t));
  for (int grid = 0; grid < 3; grid++) {
    uint32_t nameSize = 0;
    std::memcpy(&nameSize, bytes.data() + densityStart + 136, sizeof(nameSize));
    densityStart += 176 + nameSize;
  }
  densityStart += firstGridBytes;
  const uint64_t farAway = uint64_t(1) << 40;
  std::memcpy(corruptTree.data() + densityStart + sizeof(nanovdb::GridData)
                  + sizeof(uint64_t),
      &farAway,
      sizeof(farAway));
  writeAll(folder + "corrupt-tree.nvdb", corruptTree);
  return 0;
}
