// image-diff: how far apart two images are (PNG, PFM or EXR, any mix), in
// the metrics the render tests use; exits 0 within tolerance, 1 beyond it,
// 2 when an image cannot be read or the arguments are wrong.
#include "ImageIO.h"
#include "ImageMetrics.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

// The render tests' default tolerance (tests/render/tolerances.txt).
constexpr double kDefaultToleranceRmse = 0.002;
constexpr double kDefaultPixelThreshold = 1.0 / 255.0;

void printUsage(std::FILE *out)
{
  std::fprintf(out,
      "usage: image-diff A B [--tolerance-rmse X] [--threshold T] [--rgb]\n"
      "                      [--diff out.png]\n"
      "  Compares two images (.png, .pfm, .exr; linear values) channel by\n"
      "  channel over RGBA (RGB with --rgb) and prints RMSE, the largest\n"
      "  difference, PSNR and the fraction of pixels differing by more than\n"
      "  T (default 1/255). Exit status 0 when RMSE <= X (default %g), 1 when\n"
      "  not or the sizes differ, 2 on unreadable images or bad arguments.\n"
      "  --diff writes |A - B| scaled so the largest difference is white.\n",
      kDefaultToleranceRmse);
}

bool parseNumber(const char *text, double &value)
{
  char *end = nullptr;
  value = std::strtod(text, &end);
  return end != text && *end == '\0' && std::isfinite(value) && value >= 0.0;
}

} // namespace

int main(int argc, char **argv)
{
  using namespace prism::image;
  std::string paths[2];
  int pathCount = 0;
  std::string diffPath;
  double toleranceRmse = kDefaultToleranceRmse;
  double threshold = kDefaultPixelThreshold;
  Channels channels = Channels::Rgba;
  for (int i = 1; i < argc; i++) {
    const std::string argument = argv[i];
    const bool hasValue = i + 1 < argc;
    if (argument == "-h" || argument == "--help") {
      printUsage(stdout);
      return 0;
    } else if (argument == "--tolerance-rmse" && hasValue) {
      if (!parseNumber(argv[++i], toleranceRmse)) {
        std::fprintf(
            stderr, "image-diff: bad --tolerance-rmse '%s'\n", argv[i]);
        return 2;
      }
    } else if (argument == "--threshold" && hasValue) {
      if (!parseNumber(argv[++i], threshold)) {
        std::fprintf(stderr, "image-diff: bad --threshold '%s'\n", argv[i]);
        return 2;
      }
    } else if (argument == "--diff" && hasValue) {
      diffPath = argv[++i];
    } else if (argument == "--rgb") {
      channels = Channels::Rgb;
    } else if (argument.starts_with("-") || pathCount == 2) {
      printUsage(stderr);
      return 2;
    } else {
      paths[pathCount++] = argument;
    }
  }
  if (pathCount != 2) {
    printUsage(stderr);
    return 2;
  }

  Image images[2];
  for (int i = 0; i < 2; i++) {
    ReadResult result = read(paths[i]);
    if (!result.ok()) {
      std::fprintf(stderr, "image-diff: %s\n", result.error.c_str());
      return 2;
    }
    images[i] = std::move(result.image);
  }
  const Image &a = images[0], &b = images[1];
  if (a.width != b.width || a.height != b.height) {
    std::printf("sizes differ: %u x %u vs %u x %u\n",
        a.width,
        a.height,
        b.width,
        b.height);
    return 1;
  }

  const Comparison c = compare(a, b, threshold, channels);
  const bool within = c.rmse <= toleranceRmse;
  std::printf("size      %u x %u (%s)\n",
      a.width,
      a.height,
      channels == Channels::Rgb ? "RGB" : "RGBA");
  std::printf("rmse      %.6g (%.3g / 255)\n", c.rmse, c.rmse * 255.0);
  std::printf("max       %.6g\n", c.maxAbsDifference);
  std::printf("psnr      %.4g dB\n", c.psnr);
  std::printf("fraction  %.6g of pixels differ by more than %g\n",
      c.fractionDiffering,
      threshold);
  std::printf("%s: rmse %s tolerance %g\n",
      within ? "PASS" : "FAIL",
      within ? "<=" : ">",
      toleranceRmse);

  if (!diffPath.empty()) {
    Status status = write(diffPath, diffImage(a, b));
    if (!status.ok()) {
      std::fprintf(stderr, "image-diff: %s\n", status.error.c_str());
      return 2;
    }
  }
  return within ? 0 : 1;
}
