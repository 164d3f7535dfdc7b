// The NanoVDB table of contents (NanoVdbFile.*): real files written by
// NanoVDB are read; every truncation and every corrupt size is an error
// naming the file, before NanoVDB's own reader could act on it.
#include "NanoVdbFile.h"
#include "NanoVdbTestGrids.h"

#define NANOVDB_USE_ZIP
#include <nanovdb/util/IO.h>

#include <gtest/gtest.h>

#include <unistd.h>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace {

using namespace prism::vdb;
using namespace prism::render;

std::string temporaryPath()
{
  return (std::filesystem::temp_directory_path()
          / ("prism-nvdb-test-" + std::to_string(::getpid()) + ".nvdb"))
      .string();
}

// NanoVDB writes files by seeking back to their headers: through a file.
std::string gridFileBytes(nanovdb::io::Codec codec)
{
  const std::string path = temporaryPath();
  nanovdb::io::writeGrids(path, test_grids::makeTestGrids(), codec);
  std::ifstream in(path, std::ios::binary);
  std::string bytes{std::istreambuf_iterator<char>(in), {}};
  std::remove(path.c_str());
  return bytes;
}

// The contents of a file holding `bytes`, or the error.
std::string contentsOf(
    const std::string &bytes, std::vector<NanoVdbGridEntry> &grids)
{
  const std::string path = temporaryPath();
  std::ofstream(path, std::ios::binary)
      .write(bytes.data(), std::streamsize(bytes.size()));
  const std::string error = readNanoVdbContents(path, grids);
  std::remove(path.c_str());
  return error;
}

TEST(NanoVdbFile, ReadsWhatNanoVdbWrites)
{
  for (auto codec : {nanovdb::io::Codec::NONE, nanovdb::io::Codec::ZIP}) {
    std::vector<NanoVdbGridEntry> grids;
    ASSERT_EQ(contentsOf(gridFileBytes(codec), grids), "");
    ASSERT_EQ(grids.size(), 3u);
    EXPECT_EQ(grids[0].name, "velocity");
    EXPECT_FALSE(isScalarNanoVdbGridType(grids[0].gridType));
    EXPECT_EQ(grids[1].name, "density");
    EXPECT_EQ(nanoVdbGridTypeName(grids[1].gridType), "float");
    EXPECT_TRUE(isScalarNanoVdbGridType(grids[1].gridType));
    EXPECT_EQ(grids[2].index, 2u);
    EXPECT_EQ(grids[2].codec, uint16_t(codec));
  }
}

TEST(NanoVdbFile, EveryTruncationIsAnError)
{
  for (auto codec : {nanovdb::io::Codec::NONE, nanovdb::io::Codec::ZIP}) {
    const std::string bytes = gridFileBytes(codec);
    // Every length through the headers, then a stride through the grids.
    for (size_t length = 0; length < bytes.size();
         length += length < 1200 ? 1 : 499) {
      std::vector<NanoVdbGridEntry> grids;
      const std::string error = contentsOf(bytes.substr(0, length), grids);
      EXPECT_NE(error, "") << "a file cut to " << length << " bytes was read";
      EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    }
  }
}

TEST(NanoVdbFile, CorruptSizesAreErrors)
{
  const std::string bytes = gridFileBytes(nanovdb::io::Codec::NONE);
  // Offsets in the first grid's metadata (after the 16-byte header).
  struct Case
  {
    size_t offset;
    uint64_t value;
    size_t size;
    const char *fragment;
  };
  const Case cases[] = {
      {0, 0x1234, 8, "not a NanoVDB file"},         // magic
      {8, 0, 4, "version"},                         // version
      {14, 7, 2, "unknown compression codec"},      // codec
      {16 + 0, uint64_t(1) << 40, 8, "corrupt"},    // gridSize
      {16 + 8, uint64_t(1) << 40, 8, "truncated"},  // fileSize
      {16 + 136, 0xfffffff0u, 4, "grid name size"}, // nameSize
      {16 + 136, 0, 4, "grid name size"},
  };
  for (const Case &c : cases) {
    std::string corrupt = bytes;
    std::memcpy(corrupt.data() + c.offset, &c.value, c.size);
    std::vector<NanoVdbGridEntry> grids;
    const std::string error = contentsOf(corrupt, grids);
    EXPECT_NE(error.find(c.fragment), std::string::npos)
        << "offset " << c.offset << ": '" << error << "'";
  }
  std::vector<NanoVdbGridEntry> grids;
  EXPECT_NE(contentsOf(bytes + "x", grids), "") << "trailing bytes";
  // A compressed grid is allocated at the size it claims: past the
  // machine's memory, it is refused before NanoVDB allocates it.
  std::string zipped = gridFileBytes(nanovdb::io::Codec::ZIP);
  const uint64_t huge = uint64_t(1) << 50;
  std::memcpy(zipped.data() + 16, &huge, sizeof(huge));
  EXPECT_NE(contentsOf(zipped, grids)
                .find("would inflate to 1.0 PiB, more than the machine's"),
      std::string::npos)
      << contentsOf(zipped, grids);
  EXPECT_NE(contentsOf("", grids).find("is empty"), std::string::npos);
}

} // namespace
