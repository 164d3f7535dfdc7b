// prism_image: round trips, row order on disk, damaged files and metrics.
#include "ImageIO.h"
#include "ImageMetrics.h"

#include <ImfRgbaFile.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

// A private copy of the PNG decoder, to check the bytes on disk without
// going through the reader under test.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-but-set-variable"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_NO_LINEAR
#define STBI_NO_HDR
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace {

namespace fs = std::filesystem;
using namespace prism::image;

const char *kExtensions[] = {".png", ".pfm", ".exr"};

// A gradient with distinct rows, columns and channels, values in [0, 1].
Image gradient(uint32_t width, uint32_t height)
{
  Image image(width, height);
  for (uint32_t y = 0; y < height; y++) {
    for (uint32_t x = 0; x < width; x++) {
      image.at(x, y) = {float(x) / float(width - 1),
          float(y) / float(height - 1),
          float((x * 7 + y * 3) % 11) / 10.f,
          0.25f + 0.75f * float(x + y) / float(width + height - 2)};
    }
  }
  return image;
}

// Bottom row red, everything above it blue.
Image redBottomRow(uint32_t width, uint32_t height)
{
  Image image(width, height, {0.f, 0.f, 1.f, 1.f});
  for (uint32_t x = 0; x < width; x++)
    image.at(x, 0) = {1.f, 0.f, 0.f, 1.f};
  return image;
}

class ImageIO : public ::testing::Test
{
 protected:
  void SetUp() override
  {
    const auto *test = ::testing::UnitTest::GetInstance()->current_test_info();
    m_directory = fs::temp_directory_path()
                  / ("prism_image_test_" + std::to_string(::getpid()) + "_"
                      + test->name());
    fs::remove_all(m_directory);
    fs::create_directories(m_directory);
  }
  void TearDown() override
  {
    fs::remove_all(m_directory);
  }

  std::string path(const std::string &name) const
  {
    return (m_directory / name).string();
  }

  // The names in the test directory: temporaries would show up here.
  std::vector<std::string> files() const
  {
    std::vector<std::string> names;
    for (const auto &entry : fs::directory_iterator(m_directory))
      names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  fs::path m_directory;
};

TEST_F(ImageIO, PngRoundTripIsWithinHalfAnSrgbStep)
{
  Image original = gradient(37, 23);
  ASSERT_TRUE(write(path("a.png"), original).ok());
  ReadResult result = read(path("a.png"));
  ASSERT_TRUE(result.ok()) << result.error;
  ASSERT_EQ(result.image.width, 37u);
  ASSERT_EQ(result.image.height, 23u);
  for (size_t i = 0; i < original.pixels.size(); i++) {
    for (int c = 0; c < 3; c++) {
      EXPECT_NEAR(srgbFromLinear(result.image.pixels[i][c]),
          srgbFromLinear(original.pixels[i][c]),
          0.5f / 255.f + 1e-6f);
    }
    EXPECT_NEAR(result.image.pixels[i].a, original.pixels[i].a, 0.5f / 255.f);
  }
  // quantizeToSrgb8 predicts the read exactly, and is idempotent.
  EXPECT_EQ(quantizeToSrgb8(original).pixels, result.image.pixels);
  EXPECT_EQ(quantizeToSrgb8(result.image).pixels, result.image.pixels);
}

TEST_F(ImageIO, PngClampsOutOfRangeAndNaN)
{
  Image image(2, 1);
  image.at(0, 0) = {-1.f, 2.f, std::numeric_limits<float>::quiet_NaN(), 7.f};
  image.at(1, 0) = {0.5f, 0.f, 1.f, -3.f};
  ASSERT_TRUE(write(path("a.png"), image).ok());
  ReadResult result = read(path("a.png"));
  ASSERT_TRUE(result.ok()) << result.error;
  EXPECT_EQ(result.image.at(0, 0), (Rgba{0.f, 1.f, 0.f, 1.f}));
  EXPECT_EQ(result.image.at(1, 0).a, 0.f);
}

TEST_F(ImageIO, PfmRoundTripIsExactAndAlphaReadsAsOne)
{
  Image original = gradient(19, 11);
  original.at(3, 4) = {-2.5f, 1e30f, 1e-30f, 0.5f};
  ASSERT_TRUE(write(path("a.pfm"), original).ok());
  ReadResult result = read(path("a.pfm"));
  ASSERT_TRUE(result.ok()) << result.error;
  ASSERT_EQ(result.image.width, 19u);
  ASSERT_EQ(result.image.height, 11u);
  for (size_t i = 0; i < original.pixels.size(); i++) {
    Rgba expected = original.pixels[i];
    expected.a = 1.f;
    EXPECT_EQ(result.image.pixels[i], expected) << "pixel " << i;
  }
}

TEST_F(ImageIO, PfmReadsBigEndianGrayAndAppliesTheScale)
{
  // 2 x 1 gray, big endian (positive scale), values multiplied by 2.
  std::string bytes = "Pf\n2 1\n2.0\n";
  const unsigned char data[8] = {0x3f, 0x80, 0, 0, 0x40, 0x40, 0, 0}; // 1, 3
  bytes.append((const char *)data, sizeof(data));
  std::ofstream(path("g.pfm"), std::ios::binary) << bytes;
  ReadResult result = read(path("g.pfm"));
  ASSERT_TRUE(result.ok()) << result.error;
  EXPECT_EQ(result.image.at(0, 0), (Rgba{2.f, 2.f, 2.f, 1.f}));
  EXPECT_EQ(result.image.at(1, 0), (Rgba{6.f, 6.f, 6.f, 1.f}));
}

TEST_F(ImageIO, ExrFloatRoundTripIsExact)
{
  Image original = gradient(29, 17);
  original.at(1, 2) = {-2.5f, 1e30f, 1e-30f, 0.123456789f};
  ASSERT_TRUE(write(path("a.exr"), original).ok());
  ReadResult result = read(path("a.exr"));
  ASSERT_TRUE(result.ok()) << result.error;
  EXPECT_EQ(result.image.width, 29u);
  EXPECT_EQ(result.image.height, 17u);
  EXPECT_EQ(result.image.pixels, original.pixels);
}

TEST_F(ImageIO, ExrHalfRoundTripIsWithinHalfPrecision)
{
  Image original = gradient(29, 17);
  original.at(1, 2) = {-2.5f, 1000.f, 0.001f, 0.123456789f};
  ASSERT_TRUE(
      write(path("a.exr"), original, {.exrPixelType = ExrPixelType::Half})
          .ok());
  ReadResult result = read(path("a.exr"));
  ASSERT_TRUE(result.ok()) << result.error;
  for (size_t i = 0; i < original.pixels.size(); i++) {
    for (int c = 0; c < 4; c++) {
      const float value = original.pixels[i][c];
      // Round to nearest with an 11-bit significand: half an ulp is 2^-11
      // relative (normal halves; all values here are normal).
      EXPECT_NEAR(result.image.pixels[i][c], value, std::fabs(value) / 2048.f)
          << "pixel " << i << " channel " << c;
    }
  }
  EXPECT_LT(fs::file_size(path("a.exr")), 29u * 17u * 8u + 1024u);
}

TEST_F(ImageIO, RowZeroIsTheBottomInEveryFormat)
{
  const Image image = redBottomRow(4, 3);
  for (const char *extension : kExtensions) {
    const std::string file = path(std::string("o") + extension);
    ASSERT_TRUE(write(file, image).ok()) << extension;
    ReadResult result = read(file);
    ASSERT_TRUE(result.ok()) << result.error;
    EXPECT_EQ(result.image.at(2, 0), (Rgba{1.f, 0.f, 0.f, 1.f})) << extension;
    EXPECT_EQ(result.image.at(2, 2), (Rgba{0.f, 0.f, 1.f, 1.f})) << extension;
  }
}

TEST_F(ImageIO, FilesStoreRowsAsTheirFormatsSay)
{
  const Image image = redBottomRow(4, 3);
  // PNG: first row in the file is the top (blue).
  ASSERT_TRUE(write(path("o.png"), image).ok());
  int w = 0, h = 0, n = 0;
  stbi_uc *png = stbi_load(path("o.png").c_str(), &w, &h, &n, 4);
  ASSERT_NE(png, nullptr);
  EXPECT_EQ(png[0], 0);
  EXPECT_EQ(png[2], 255);
  EXPECT_EQ(png[(h - 1) * w * 4 + 0], 255);
  stbi_image_free(png);
  // EXR: scan line at the data window's min.y is the top.
  ASSERT_TRUE(write(path("o.exr"), image).ok());
  Imf::RgbaInputFile exr(path("o.exr").c_str());
  std::vector<Imf::Rgba> rows(12);
  exr.setFrameBuffer(rows.data(), 1, 4);
  exr.readPixels(0, 2);
  EXPECT_EQ(float(rows[0].b), 1.f);
  EXPECT_EQ(float(rows[8].r), 1.f);
  // PFM: rows run bottom to top, so the first float is the red bottom row.
  ASSERT_TRUE(write(path("o.pfm"), image).ok());
  std::ifstream pfm(path("o.pfm"), std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(pfm)), {});
  ASSERT_EQ(bytes.substr(0, 12), "PF\n4 3\n-1.0\n");
  float first[3];
  std::memcpy(first, bytes.data() + 12, sizeof(first)); // little-endian host
  EXPECT_EQ(first[0], 1.f);
  EXPECT_EQ(first[2], 0.f);
}

TEST_F(ImageIO, TruncatedFilesAreErrors)
{
  const Image image = gradient(64, 48);
  for (const char *extension : kExtensions) {
    const std::string file = path(std::string("t") + extension);
    ASSERT_TRUE(write(file, image).ok()) << extension;
    const auto full = fs::file_size(file);
    for (auto size : {full - 1,
             full / 2,
             full / 8,
             uintmax_t(20),
             uintmax_t(3),
             uintmax_t(0)}) {
      ASSERT_TRUE(write(file, image).ok());
      fs::resize_file(file, size);
      ReadResult result = read(file);
      EXPECT_FALSE(result.ok())
          << extension << " truncated to " << size << " of " << full;
      EXPECT_NE(result.error.find(file), std::string::npos) << result.error;
    }
  }
}

TEST_F(ImageIO, CorruptFilesAreErrorsOrImagesButNeverCrashes)
{
  const Image image = gradient(64, 48);
  for (const char *extension : kExtensions) {
    const std::string file = path(std::string("c") + extension);
    // Not the format at all.
    std::ofstream(file, std::ios::binary) << "this is not an image at all";
    EXPECT_FALSE(read(file).ok()) << extension;
    // Damaged bytes all through the file, header included: whatever comes
    // back, it comes back as a value.
    for (size_t stride : {7, 61, 997}) {
      ASSERT_TRUE(write(file, image).ok());
      std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
      std::string bytes((std::istreambuf_iterator<char>(f)), {});
      for (size_t i = stride / 2; i < bytes.size(); i += stride)
        bytes[i] = char(bytes[i] ^ 0x5a);
      f.seekp(0);
      f.write(bytes.data(), std::streamsize(bytes.size()));
      f.close();
      ReadResult result = read(file);
      if (result.ok()) {
        EXPECT_EQ(result.image.pixels.size(),
            size_t(result.image.width) * result.image.height);
      }
    }
  }
  std::ofstream(path("huge.pfm"), std::ios::binary)
      << "PF\n999999 999999\n-1\n";
  EXPECT_NE(read(path("huge.pfm")).error.find("limit"), std::string::npos);
}

TEST_F(ImageIO, ErrorsNameTheFileAndTheReason)
{
  ReadResult missing = read(path("missing.png"));
  EXPECT_FALSE(missing.ok());
  EXPECT_NE(missing.error.find("missing.png"), std::string::npos);
  EXPECT_NE(missing.error.find("No such file"), std::string::npos);
  EXPECT_NE(
      read(path("a.tiff")).error.find("unknown extension"), std::string::npos);
  EXPECT_FALSE(write(path("a.tiff"), gradient(2, 2)).ok());
  EXPECT_FALSE(write(path("a.png"), Image{}).ok());
  Image inconsistent(4, 4);
  inconsistent.pixels.pop_back();
  EXPECT_FALSE(write(path("a.png"), inconsistent).ok());
  EXPECT_FALSE(write(path("no/such/folder/a.png"), gradient(2, 2)).ok());
  EXPECT_TRUE(files().empty());
}

TEST_F(ImageIO, WritesLeaveNoTemporariesAndReplaceWholeFiles)
{
  for (const char *extension : kExtensions) {
    const std::string file = path(std::string("w") + extension);
    ASSERT_TRUE(write(file, gradient(8, 8)).ok());
    ASSERT_TRUE(write(file, redBottomRow(3, 2)).ok());
    ReadResult result = read(file);
    ASSERT_TRUE(result.ok()) << result.error;
    EXPECT_EQ(result.image.width, 3u);
  }
  EXPECT_EQ(files(), (std::vector<std::string>{"w.exr", "w.pfm", "w.png"}));
  // A failed write leaves the old file in place.
  ASSERT_TRUE(write(path("keep.png"), gradient(8, 8)).ok());
  EXPECT_FALSE(write(path("keep.png"), Image{}).ok());
  EXPECT_EQ(read(path("keep.png")).image.width, 8u);
}

TEST_F(ImageIO, ExtensionsAreCaseInsensitive)
{
  ASSERT_TRUE(write(path("A.PNG"), gradient(4, 4)).ok());
  EXPECT_TRUE(read(path("A.PNG")).ok());
}

TEST(ImageMetrics, ConstantImagesDifferByTheirDifference)
{
  const Image a(8, 4, {0.2f, 0.2f, 0.2f, 1.f});
  const Image b(8, 4, {0.5f, 0.5f, 0.5f, 1.f});
  // RGB: every value 0.3 apart. RGBA: alpha adds zeros.
  EXPECT_NEAR(rmse(a, b, Channels::Rgb), 0.3, 1e-7);
  EXPECT_NEAR(rmse(a, b, Channels::Rgba), 0.3 * std::sqrt(0.75), 1e-7);
  EXPECT_NEAR(maxAbsDifference(a, b), 0.3, 1e-7);
  EXPECT_NEAR(psnr(a, b, Channels::Rgb), 20.0 * std::log10(1.0 / 0.3), 1e-5);
  EXPECT_EQ(fractionDiffering(a, b, 0.1), 1.0);
  EXPECT_EQ(fractionDiffering(a, b, 0.5), 0.0);
  EXPECT_EQ(rmse(a, a), 0.0);
  EXPECT_EQ(psnr(a, a), std::numeric_limits<double>::infinity());
}

TEST(ImageMetrics, FractionCountsPixelsNotChannels)
{
  const Image a(10, 10, {0.f, 0.f, 0.f, 1.f});
  Image b = a;
  b.at(0, 0) = {0.5f, 0.5f, 0.5f, 1.f};
  b.at(9, 9).a = 0.f;
  EXPECT_DOUBLE_EQ(fractionDiffering(a, b, 0.1, Channels::Rgba), 0.02);
  EXPECT_DOUBLE_EQ(fractionDiffering(a, b, 0.1, Channels::Rgb), 0.01);
  const Comparison c = compare(a, b, 0.1, Channels::Rgb);
  EXPECT_DOUBLE_EQ(c.maxAbsDifference, 0.5);
  EXPECT_DOUBLE_EQ(c.fractionDiffering, 0.01);
  EXPECT_NEAR(c.rmse, std::sqrt(3 * 0.25 / 300.0), 1e-12);
}

TEST(ImageMetrics, SizeMismatchAndNaNAreInfinitelyFar)
{
  const Image a(4, 4, {0.f, 0.f, 0.f, 1.f});
  const Image b(4, 3, {0.f, 0.f, 0.f, 1.f});
  EXPECT_EQ(rmse(a, b), std::numeric_limits<double>::infinity());
  EXPECT_EQ(fractionDiffering(a, b, 0.5), 1.0);
  EXPECT_TRUE(diffImage(a, b).empty());
  Image nan = a;
  nan.at(1, 1).g = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(rmse(a, nan), std::numeric_limits<double>::infinity());
  EXPECT_EQ(maxAbsDifference(a, nan), std::numeric_limits<double>::infinity());
  EXPECT_EQ(rmse(nan, nan), 0.0);
}

TEST(ImageMetrics, DiffImageScalesTheLargestDifferenceToOne)
{
  const Image a(2, 1, {0.f, 0.f, 0.f, 1.f});
  Image b = a;
  b.at(0, 0) = {0.01f, 0.005f, 0.f, 0.f};
  const Image diff = diffImage(a, b);
  EXPECT_FLOAT_EQ(diff.at(0, 0).r, 1.f);
  EXPECT_FLOAT_EQ(diff.at(0, 0).g, 0.5f);
  EXPECT_EQ(diff.at(1, 0), (Rgba{0.f, 0.f, 0.f, 1.f}));
  EXPECT_FLOAT_EQ(diffImage(a, b, 10.f).at(0, 0).r, 0.1f);
}

} // namespace
