// glTF animations sampled at one time: the nodes' translation, rotation,
// scale and morph weights as the file's channels give them at `time`
// (seconds; before the first key the first value, after the last the
// last), with glTF's STEP, LINEAR (spherical for rotations) and
// CUBICSPLINE interpolation.
#pragma once

#include <tiny_gltf.h>

#include <string>
#include <vector>

namespace prism::scene_io {

// Reads an accessor of floats whose elements have `minComponents` to
// `maxComponents` values each, flattened; false with `error` when it
// cannot. (The loader's own checked reader.)
using FloatAccessorReader = bool (*)(const tinygltf::Model &model,
    int accessor,
    int minComponents,
    int maxComponents,
    std::vector<float> &values,
    std::string &error);

// Poses `model`'s nodes as every animation's channels give them at `time`;
// the error names the animation, channel and problem.
bool poseAtTime(tinygltf::Model &model,
    double time,
    FloatAccessorReader read,
    std::string &error);

} // namespace prism::scene_io
