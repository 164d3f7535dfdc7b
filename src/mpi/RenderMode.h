// The device parameter `mode`: how the processes of a communicator share a
// frame.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace prism::mpi {

enum class RenderMode : uint32_t {
  // True data-parallel path tracing: every ray meets every process's part
  // of the world; the process owning a hit shades it (the default).
  PathTracer,
  // Each process renders its own part of the world; depth-sorted
  // compositing of their pixels (visibility exact, shading local).
  Composite,
  // Every process holds the whole world; each renders a share of the tiles.
  Replicated,
};

// nullopt for names that are not a mode this device implements.
inline std::optional<RenderMode> parseRenderMode(const std::string &name)
{
  if (name == "pathtracer")
    return RenderMode::PathTracer;
  if (name == "composite")
    return RenderMode::Composite;
  if (name == "replicated")
    return RenderMode::Replicated;
  return std::nullopt;
}

inline const char *toString(RenderMode mode)
{
  switch (mode) {
  case RenderMode::PathTracer:
    return "pathtracer";
  case RenderMode::Composite:
    return "composite";
  case RenderMode::Replicated:
    break;
  }
  return "replicated";
}

} // namespace prism::mpi
