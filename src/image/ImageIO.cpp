#include "ImageIO.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <new>

// stb is compiled here with static linkage, so no other copy of it (Debian's
// libstb, another library's) can clash with ours at link time.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-but-set-variable"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_NO_STDIO
#define STBI_NO_LINEAR
#define STBI_NO_HDR
#include <stb/stb_image.h>
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace prism::image {

namespace {

// 64 Mpixel (1 GiB as float RGBA): a corrupt header cannot make us allocate
// more than this.
constexpr uint64_t kMaxPixelCount = uint64_t(1) << 26;

using Bytes = std::vector<unsigned char>;

std::string quoted(const std::string &path)
{
  return "'" + path + "'";
}

std::string lowerExtension(const std::string &path)
{
  std::string extension = std::filesystem::path(path).extension().string();
  for (char &c : extension)
    c = char(std::tolower((unsigned char)c));
  return extension;
}

std::string checkSize(uint64_t width, uint64_t height)
{
  if (width == 0 || height == 0)
    return "has no pixels";
  if (width * height > kMaxPixelCount)
    return "is " + std::to_string(width) + " x " + std::to_string(height)
           + ", more than the 64 Mpixel limit";
  return {};
}

// Top-to-bottom rows (files) <-> bottom-to-top rows (Image), either way.
void flipRows(std::vector<Rgba> &pixels, uint32_t width, uint32_t height)
{
  for (uint32_t y = 0; y < height / 2; y++) {
    std::swap_ranges(pixels.begin() + size_t(y) * width,
        pixels.begin() + size_t(y + 1) * width,
        pixels.begin() + size_t(height - 1 - y) * width);
  }
}

// Files beyond 2 GiB are not images we read (and stb takes an int length).
Status readFile(const std::string &path, Bytes &bytes)
{
  std::FILE *file = std::fopen(path.c_str(), "rb");
  if (!file)
    return {"cannot open " + quoted(path) + ": " + std::strerror(errno)};
  bytes.clear();
  unsigned char chunk[65536];
  size_t got = 0;
  while ((got = std::fread(chunk, 1, sizeof(chunk), file)) > 0) {
    if (bytes.size() + got > (size_t(1) << 31)) {
      std::fclose(file);
      return {"cannot read " + quoted(path) + ": larger than 2 GiB"};
    }
    bytes.insert(bytes.end(), chunk, chunk + got);
  }
  const bool failed = std::ferror(file);
  std::fclose(file);
  if (failed)
    return {"cannot read " + quoted(path) + ": " + std::strerror(errno)};
  return {};
}

// A name beside `path` that no other writer (thread or process) uses.
std::string temporaryPathFor(const std::string &path)
{
  static std::atomic<unsigned> counter{0};
  return path + ".tmp" + std::to_string(::getpid()) + "-"
         + std::to_string(counter++);
}

// Runs `writeTo(temporary)`, then renames the temporary over `path`; on any
// failure the temporary is removed and `path` is left as it was.
Status writeAtomically(const std::string &path,
    const std::function<Status(const std::string &)> &writeTo)
{
  const std::string temporary = temporaryPathFor(path);
  Status status;
  try {
    status = writeTo(temporary);
  } catch (const std::exception &e) {
    status = {"cannot write " + quoted(path) + ": " + e.what()};
  } catch (...) {
    status = {"cannot write " + quoted(path) + ": unknown error"};
  }
  std::error_code ignored;
  if (!status.ok()) {
    std::filesystem::remove(temporary, ignored);
    return status;
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, ignored);
    return {"cannot write " + quoted(path) + ": " + error.message()};
  }
  return {};
}

Status writeBytes(const std::string &path, const Bytes &bytes)
{
  return writeAtomically(path, [&](const std::string &temporary) -> Status {
    std::FILE *file = std::fopen(temporary.c_str(), "wb");
    if (!file)
      return {
          "cannot create " + quoted(temporary) + ": " + std::strerror(errno)};
    const bool written =
        std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    // fclose flushes: a full disk can first show up here.
    const bool closed = std::fclose(file) == 0;
    if (!written || !closed)
      return {
          "cannot write " + quoted(temporary) + ": " + std::strerror(errno)};
    return {};
  });
}

uint8_t encodeSrgb8(float linear)
{
  return uint8_t(srgbFromLinear(linear) * 255.f + 0.5f);
}

uint8_t encodeUnorm8(float value)
{
  const float clamped = value > 0.f ? std::min(value, 1.f) : 0.f;
  return uint8_t(clamped * 255.f + 0.5f);
}

// Linear values of the 256 sRGB codes, so decoding is exact and repeatable.
const std::array<float, 256> &linearFromSrgb8()
{
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; i++)
      t[i] = linearFromSrgb(float(i) / 255.f);
    return t;
  }();
  return table;
}

// ---------------------------------------------------------------------------
// PNG

uint32_t crc32(const unsigned char *data, size_t size)
{
  static const std::array<uint32_t, 256> table = [] {
    std::array<uint32_t, 256> t{};
    for (uint32_t n = 0; n < 256; n++) {
      uint32_t c = n;
      for (int k = 0; k < 8; k++)
        c = (c & 1) ? 0xedb88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  uint32_t c = 0xffffffffu;
  for (size_t i = 0; i < size; i++)
    c = table[(c ^ data[i]) & 0xff] ^ (c >> 8);
  return c ^ 0xffffffffu;
}

uint32_t bigEndian32(const unsigned char *b)
{
  return uint32_t(b[0]) << 24 | uint32_t(b[1]) << 16 | uint32_t(b[2]) << 8
         | uint32_t(b[3]);
}

// stb neither checks CRCs nor needs the file's end, so a truncated or
// damaged PNG could decode silently: walk the chunks first.
std::string checkPngChunks(const Bytes &bytes)
{
  static const unsigned char kSignature[8] = {
      0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kSignature, 8) != 0)
    return "not a PNG file (bad signature)";
  size_t cursor = 8;
  while (bytes.size() - cursor >= 12) {
    const uint64_t length = bigEndian32(bytes.data() + cursor);
    if (bytes.size() - cursor - 12 < length)
      return "truncated PNG (a chunk runs past the end of the file)";
    const unsigned char *type = bytes.data() + cursor + 4;
    const uint32_t stored = bigEndian32(type + 4 + length);
    if (crc32(type, 4 + length) != stored)
      return "corrupt PNG (chunk '" + std::string((const char *)type, 4)
             + "' fails its CRC)";
    cursor += 12 + length;
    if (std::memcmp(type, "IEND", 4) == 0)
      return {};
  }
  return "truncated PNG (no IEND chunk)";
}

ReadResult readPng(const std::string &path)
{
  Bytes bytes;
  if (Status status = readFile(path, bytes); !status.ok())
    return {{}, status.error};
  if (std::string problem = checkPngChunks(bytes); !problem.empty())
    return {{}, "cannot read " + quoted(path) + ": " + problem};
  const auto *data = bytes.data();
  const int length = int(bytes.size());
  int width = 0, height = 0, channels = 0;
  if (!stbi_info_from_memory(data, length, &width, &height, &channels))
    return {{},
        "cannot read " + quoted(path) + ": not a PNG file ("
            + stbi_failure_reason() + ")"};
  if (std::string problem = checkSize(uint64_t(width), uint64_t(height));
      !problem.empty())
    return {{}, "cannot read " + quoted(path) + ": the image " + problem};
  Image image{uint32_t(width), uint32_t(height)};
  if (stbi_is_16_bit_from_memory(data, length)) {
    stbi_us *pixels =
        stbi_load_16_from_memory(data, length, &width, &height, &channels, 4);
    if (!pixels)
      return {{},
          "cannot read " + quoted(path) + ": corrupt PNG ("
              + stbi_failure_reason() + ")"};
    for (size_t i = 0; i < image.pixels.size(); i++) {
      const stbi_us *p = pixels + 4 * i;
      image.pixels[i] = {linearFromSrgb(p[0] / 65535.f),
          linearFromSrgb(p[1] / 65535.f),
          linearFromSrgb(p[2] / 65535.f),
          p[3] / 65535.f};
    }
    stbi_image_free(pixels);
  } else {
    stbi_uc *pixels =
        stbi_load_from_memory(data, length, &width, &height, &channels, 4);
    if (!pixels)
      return {{},
          "cannot read " + quoted(path) + ": corrupt PNG ("
              + stbi_failure_reason() + ")"};
    const auto &decode = linearFromSrgb8();
    for (size_t i = 0; i < image.pixels.size(); i++) {
      const stbi_uc *p = pixels + 4 * i;
      image.pixels[i] = {
          decode[p[0]], decode[p[1]], decode[p[2]], p[3] / 255.f};
    }
    stbi_image_free(pixels);
  }
  flipRows(image.pixels, image.width, image.height);
  return {std::move(image), {}};
}

void appendBytes(void *context, void *data, int size)
{
  auto *bytes = (Bytes *)context;
  bytes->insert(
      bytes->end(), (unsigned char *)data, (unsigned char *)data + size);
}

Status writePng(const std::string &path, const Image &image)
{
  if (image.width > uint32_t(INT32_MAX / 4))
    return {"cannot write " + quoted(path) + ": too wide for PNG"};
  std::vector<uint8_t> encoded(image.pixels.size() * 4);
  for (uint32_t y = 0; y < image.height; y++) {
    // PNG rows run top to bottom.
    uint8_t *row =
        encoded.data() + size_t(image.height - 1 - y) * image.width * 4;
    for (uint32_t x = 0; x < image.width; x++) {
      const Rgba &p = image.at(x, y);
      row[4 * x + 0] = encodeSrgb8(p.r);
      row[4 * x + 1] = encodeSrgb8(p.g);
      row[4 * x + 2] = encodeSrgb8(p.b);
      row[4 * x + 3] = encodeUnorm8(p.a);
    }
  }
  Bytes bytes;
  if (!stbi_write_png_to_func(appendBytes,
          &bytes,
          int(image.width),
          int(image.height),
          4,
          encoded.data(),
          int(image.width * 4)))
    return {"cannot write " + quoted(path) + ": PNG encoding failed"};
  return writeBytes(path, bytes);
}

// ---------------------------------------------------------------------------
// PFM: "PF" (RGB) or "Pf" (gray), width, height, scale (negative: little
// endian; |scale| multiplies the values), then float rows bottom to top.

// The next whitespace-separated token at `cursor`, or empty at the end.
std::string nextToken(const Bytes &bytes, size_t &cursor)
{
  while (cursor < bytes.size() && std::isspace(bytes[cursor]))
    cursor++;
  std::string token;
  while (cursor < bytes.size() && !std::isspace(bytes[cursor])
         && token.size() < 64)
    token.push_back(char(bytes[cursor++]));
  return token;
}

bool parseUnsigned(const std::string &token, uint64_t &value)
{
  if (token.empty() || token.size() > 9)
    return false;
  value = 0;
  for (char c : token) {
    if (c < '0' || c > '9')
      return false;
    value = value * 10 + uint64_t(c - '0');
  }
  return true;
}

ReadResult readPfm(const std::string &path)
{
  Bytes bytes;
  if (Status status = readFile(path, bytes); !status.ok())
    return {{}, status.error};
  const std::string corrupt = "cannot read " + quoted(path) + ": ";
  size_t cursor = 0;
  const std::string magic = nextToken(bytes, cursor);
  if (magic != "PF" && magic != "Pf")
    return {{}, corrupt + "not a PFM file (no 'PF' or 'Pf' header)"};
  const int channels = magic == "PF" ? 3 : 1;
  uint64_t width = 0, height = 0;
  if (!parseUnsigned(nextToken(bytes, cursor), width)
      || !parseUnsigned(nextToken(bytes, cursor), height))
    return {{}, corrupt + "bad PFM width or height"};
  if (std::string problem = checkSize(width, height); !problem.empty())
    return {{}, corrupt + "the image " + problem};
  const std::string scaleToken = nextToken(bytes, cursor);
  char *end = nullptr;
  const double scale = std::strtod(scaleToken.c_str(), &end);
  if (scaleToken.empty() || *end != '\0' || !std::isfinite(scale)
      || scale == 0.0)
    return {{}, corrupt + "bad PFM scale '" + scaleToken + "'"};
  // Exactly one whitespace character separates the header from the data.
  if (cursor >= bytes.size() || !std::isspace(bytes[cursor]))
    return {{}, corrupt + "PFM header is not followed by data"};
  cursor++;
  const size_t valueCount = size_t(width * height) * channels;
  if (bytes.size() - cursor < valueCount * 4)
    return {{},
        corrupt + "truncated PFM data (" + std::to_string(valueCount * 4)
            + " bytes expected, " + std::to_string(bytes.size() - cursor)
            + " present)"};
  const bool littleEndian = scale < 0.0;
  const float magnitude = float(std::fabs(scale));
  std::vector<float> values(valueCount);
  for (size_t i = 0; i < valueCount; i++) {
    const unsigned char *b = bytes.data() + cursor + 4 * i;
    const uint32_t bits =
        littleEndian ? uint32_t(b[0]) | uint32_t(b[1]) << 8
                           | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24
                     : uint32_t(b[3]) | uint32_t(b[2]) << 8
                           | uint32_t(b[1]) << 16 | uint32_t(b[0]) << 24;
    values[i] = std::bit_cast<float>(bits);
    if (magnitude != 1.f)
      values[i] *= magnitude;
  }
  Image image{uint32_t(width), uint32_t(height)};
  for (size_t i = 0; i < image.pixels.size(); i++) {
    const float *v = values.data() + i * channels;
    image.pixels[i] = channels == 3 ? Rgba{v[0], v[1], v[2], 1.f}
                                    : Rgba{v[0], v[0], v[0], 1.f};
  }
  return {std::move(image), {}};
}

Status writePfm(const std::string &path, const Image &image)
{
  const std::string header = "PF\n" + std::to_string(image.width) + " "
                             + std::to_string(image.height) + "\n-1.0\n";
  Bytes bytes(header.begin(), header.end());
  bytes.reserve(bytes.size() + image.pixels.size() * 12);
  for (const Rgba &p : image.pixels) {
    for (float value : {p.r, p.g, p.b}) {
      const uint32_t bits = std::bit_cast<uint32_t>(value);
      for (int shift = 0; shift < 32; shift += 8)
        bytes.push_back((unsigned char)(bits >> shift)); // little endian
    }
  }
  return writeBytes(path, bytes);
}

// ---------------------------------------------------------------------------
// EXR

ReadResult readExr(const std::string &path)
{
  const std::string failed = "cannot read " + quoted(path) + ": ";
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    const int64_t width = int64_t(window.max.x) - window.min.x + 1;
    const int64_t height = int64_t(window.max.y) - window.min.y + 1;
    if (width <= 0 || height <= 0)
      return {{}, failed + "empty EXR data window"};
    if (std::string problem = checkSize(uint64_t(width), uint64_t(height));
        !problem.empty())
      return {{}, failed + "the image " + problem};
    Image image{uint32_t(width), uint32_t(height)};
    const Imf::ChannelList &channels = file.header().channels();
    if (channels.findChannel("R") || channels.findChannel("G")
        || channels.findChannel("B")) {
      // The general interface reads half and float channels alike as float.
      Imf::FrameBuffer frameBuffer;
      const char *names[4] = {"R", "G", "B", "A"};
      for (int c = 0; c < 4; c++) {
        frameBuffer.insert(names[c],
            Imf::Slice::Make(Imf::FLOAT,
                &image.pixels[0][c],
                window,
                sizeof(Rgba),
                sizeof(Rgba) * size_t(width),
                1,
                1,
                c == 3 ? 1.0 : 0.0));
      }
      file.setFrameBuffer(frameBuffer);
      file.readPixels(window.min.y, window.max.y);
    } else {
      // Luminance (Y, RY, BY) files: the RGBA interface converts them.
      Imf::RgbaInputFile rgbaFile(path.c_str());
      std::vector<Imf::Rgba> halves(image.pixels.size());
      rgbaFile.setFrameBuffer(
          halves.data() - window.min.x - window.min.y * width,
          1,
          size_t(width));
      rgbaFile.readPixels(window.min.y, window.max.y);
      for (size_t i = 0; i < halves.size(); i++)
        image.pixels[i] = {halves[i].r, halves[i].g, halves[i].b, halves[i].a};
    }
    flipRows(image.pixels, image.width, image.height);
    return {std::move(image), {}};
  } catch (const std::bad_alloc &) {
    return {{}, failed + "out of memory"};
  } catch (const std::exception &e) {
    return {{}, failed + e.what()};
  } catch (...) {
    return {{}, failed + "unknown error"};
  }
}

Status writeExr(
    const std::string &path, const Image &image, ExrPixelType pixelType)
{
  if (image.width > uint32_t(INT32_MAX) || image.height > uint32_t(INT32_MAX))
    return {"cannot write " + quoted(path) + ": too large for EXR"};
  std::vector<Rgba> topDown = image.pixels;
  flipRows(topDown, image.width, image.height);
  const int width = int(image.width), height = int(image.height);
  return writeAtomically(path, [&](const std::string &temporary) -> Status {
    if (pixelType == ExrPixelType::Half) {
      std::vector<Imf::Rgba> halves(topDown.size());
      for (size_t i = 0; i < topDown.size(); i++)
        halves[i] =
            Imf::Rgba(topDown[i].r, topDown[i].g, topDown[i].b, topDown[i].a);
      Imf::RgbaOutputFile file(
          temporary.c_str(), width, height, Imf::WRITE_RGBA);
      file.setFrameBuffer(halves.data(), 1, size_t(width));
      file.writePixels(height);
      return {};
    }
    Imf::Header header(width, height);
    Imf::FrameBuffer frameBuffer;
    const char *names[4] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; c++) {
      header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
      frameBuffer.insert(names[c],
          Imf::Slice(Imf::FLOAT,
              (char *)&topDown[0][c],
              sizeof(Rgba),
              sizeof(Rgba) * size_t(width)));
    }
    // The file is complete (offset table written) once it is destroyed.
    Imf::OutputFile file(temporary.c_str(), header);
    file.setFrameBuffer(frameBuffer);
    file.writePixels(height);
    return {};
  });
}

} // namespace

float srgbFromLinear(float linear)
{
  if (!(linear > 0.f)) // also NaN
    return 0.f;
  if (linear >= 1.f)
    return 1.f;
  return linear <= 0.0031308f ? 12.92f * linear
                              : 1.055f * std::pow(linear, 1.f / 2.4f) - 0.055f;
}

float linearFromSrgb(float srgb)
{
  if (!(srgb > 0.f))
    return 0.f;
  if (srgb >= 1.f)
    return 1.f;
  return srgb <= 0.04045f ? srgb / 12.92f
                          : std::pow((srgb + 0.055f) / 1.055f, 2.4f);
}

Image quantizeToSrgb8(const Image &image)
{
  const auto &decode = linearFromSrgb8();
  Image out = image;
  for (Rgba &p : out.pixels) {
    p = {decode[encodeSrgb8(p.r)],
        decode[encodeSrgb8(p.g)],
        decode[encodeSrgb8(p.b)],
        encodeUnorm8(p.a) / 255.f};
  }
  return out;
}

ReadResult read(const std::string &path)
{
  const std::string extension = lowerExtension(path);
  if (extension == ".png")
    return readPng(path);
  if (extension == ".pfm")
    return readPfm(path);
  if (extension == ".exr")
    return readExr(path);
  return {{},
      "cannot read " + quoted(path)
          + ": unknown extension (expected .png, .pfm or .exr)"};
}

Status write(
    const std::string &path, const Image &image, const WriteOptions &options)
{
  if (image.width == 0 || image.height == 0
      || image.pixels.size() != size_t(image.width) * image.height)
    return {"cannot write " + quoted(path) + ": the image is "
            + std::to_string(image.width) + " x " + std::to_string(image.height)
            + " but holds " + std::to_string(image.pixels.size()) + " pixels"};
  const std::string extension = lowerExtension(path);
  try {
    if (extension == ".png")
      return writePng(path, image);
    if (extension == ".pfm")
      return writePfm(path, image);
    if (extension == ".exr")
      return writeExr(path, image, options.exrPixelType);
  } catch (const std::bad_alloc &) {
    return {"cannot write " + quoted(path) + ": out of memory"};
  }
  return {"cannot write " + quoted(path)
          + ": unknown extension (expected .png, .pfm or .exr)"};
}

} // namespace prism::image
