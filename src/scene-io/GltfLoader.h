// glTF 2.0 (.gltf, .glb; via tinygltf) to an ANARI world:
// - each mesh becomes one group (one surface per primitive: triangles,
//   points as spheres, lines as curves), and every node using the mesh
//   places that shared group: one `transform` instance with an array of
//   matrices when the device has KHR_INSTANCE_TRANSFORM_ARRAY, one instance
//   per node otherwise; normal-mapped primitives without TANGENT get
//   MikkTSpace tangents;
// - materials become `physicallyBased` with the spec's glTF mapping and
//   glTF's defaults (specular 1): factors scale textures through the
//   samplers' outTransform, channels are swizzled the same way (roughness G,
//   metallic B, occlusion R, ...), KHR_texture_transform becomes
//   inTransform/inOffset, the KHR_materials_* extensions map onto their
//   parameters, specular-glossiness is converted, and unlit, COLOR_0 times
//   a texture and doubleSided use prism's extensions (docs/extensions.md);
// - cameras and KHR_lights_punctual come out in world space; the scene
//   says whether anything emits light.
// Files that need Draco, KTX2 or meshopt are refused by name (GltfSupport.h).
// Every index is checked in the JSON as written (GltfIndexCheck.h) and every
// accessor bounds-checked: a corrupt file is an error, never a crash or
// another object silently used.
#pragma once

#include "LoadResult.h"

#include <anari/anari.h>

#include <optional>
#include <string>

namespace prism::scene_io {

struct GltfOptions
{
  int cameraIndex{-1}; // glTF camera to view through; -1: the first found
  // KHR_materials_variants: the variant whose materials primitives use;
  // empty: their default materials.
  std::string variant;
  // Animations sampled at this time (seconds); unset: not played.
  std::optional<double> time;
  // False: buffers and images must be inside the file (GLB chunk or data
  // URI); external URIs fail as missing files (fuzzing).
  bool readExternalFiles{true};
};

// Reads the file at `path` and loads it as below.
LoadResult loadGltf(
    ANARIDevice device, const std::string &path, const GltfOptions &options);

// A .gltf or .glb held in memory (the magic decides which); `path` names it
// in messages and external URIs resolve in its folder.
LoadResult loadGltfFromMemory(ANARIDevice device,
    const std::string &bytes,
    const std::string &path,
    const GltfOptions &options);

} // namespace prism::scene_io
