// prism-render's command line: every option, parsed and checked before any
// device is loaded, so a bad argument costs nothing and names itself.
#pragma once

#include "VolumeStyle.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace prism::render {

using Vec3 = std::array<float, 3>;

// How volumes are colored (--tf-*), as the scene loaders take it.
using scene_io::TransferFunctionOptions;

struct Options
{
  std::string scene;  // a file path or demo:<name>
  std::string output; // empty: <scene name>.png in the working directory
  uint32_t width{1024};
  uint32_t height{768};
  uint32_t samplesPerPixel{1};
  std::string renderer{"default"};
  // --param name=value, in command-line order; typed later by introspection.
  std::vector<std::pair<std::string, std::string>> rendererParameters;

  std::optional<Vec3> eye, at, up;
  std::optional<float> fovyDegrees;
  int cameraIndex{-1};        // glTF camera to use; -1: the first in the scene
  std::string variant;        // glTF material variant (KHR_materials_variants)
  std::optional<double> time; // glTF animations at this time (seconds)
  std::optional<std::array<float, 4>> background;
  // The environment lighting the scene (scene_io::lightingFor): "studio",
  // "none", or an equirectangular image file; `environmentGiven` when
  // --env chose it rather than the default.
  std::string environment{"studio"};
  bool environmentGiven{false};
  float environmentIntensity{1.f};
  float environmentRotateDegrees{0.f};

  std::string depthPath, normalPath, albedoPath, idsPrefix;
  bool denoise{false};
  // With a data-parallel device: build only this process's share of the
  // scene's surfaces and volumes (scenes/Partition.h).
  bool mpiPartition{false};

  std::string library{"prism"};
  // Records the run through the debug layer into this trace (empty: no trace).
  std::string traceFile;
  std::string deviceSubtype{"default"};
  uint32_t benchFrames{0};
  uint32_t threads{0}; // 0: the device's choice

  // Raw volumes: dimensions, element type and voxel spacing.
  std::optional<std::array<uint64_t, 3>> rawDimensions;
  std::string rawType;
  Vec3 rawSpacing{1.f, 1.f, 1.f};
  // NanoVDB files: the grid to render; empty: the first scalar grid.
  std::string gridName;
  TransferFunctionOptions transferFunction;

  bool quiet{false};
  bool verbose{false};
  bool help{false};
  bool listDemos{false};
};

struct ParseResult
{
  Options options;
  std::string error; // empty on success; names the option and the problem

  bool ok() const
  {
    return error.empty();
  }
};

ParseResult parseOptions(int argc, const char *const *argv);

// The --help text.
std::string helpText();

// Whether `path` ends in an image format prism-render writes (.png, .exr,
// .pfm), case-insensitively.
bool isImagePath(const std::string &path);

// Parsers shared with --param: "x,y,z" floats and the like. Each returns
// false on anything but exactly `count` finite numbers.
bool parseFloats(const std::string &text, float *values, int count);

} // namespace prism::render
