// What the prism device is and implements: its version, and the one list of
// extensions and renderer subtypes introspection reports (a test creates
// every advertised subtype and checks it is implemented).
#pragma once

#include <cstdint>

namespace prism {

constexpr int kVersionMajor = 0;
constexpr int kVersionMinor = 1;
constexpr int kVersionPatch = 0;
constexpr const char *kDeviceName = "Prism CPU device";
// Indices are read as 32- or 64-bit; Embree addresses 32-bit primitive ids.
constexpr uint64_t kGeometryMaxIndex = 0xffffffffull;

inline const char *kImplementedExtensions[] = {
    "ANARI_KHR_ARRAY1D_REGION",
    "ANARI_KHR_CAMERA_DEPTH_OF_FIELD",
    "ANARI_KHR_CAMERA_MOTION_TRANSFORMATION",
    "ANARI_KHR_CAMERA_OMNIDIRECTIONAL",
    "ANARI_KHR_CAMERA_ORTHOGRAPHIC",
    "ANARI_KHR_CAMERA_PERSPECTIVE",
    "ANARI_KHR_CAMERA_ROLLING_SHUTTER",
    "ANARI_KHR_CAMERA_SHUTTER",
    "ANARI_KHR_CAMERA_STEREO",
    "ANARI_KHR_DEVICE_SYNCHRONIZATION",
    "ANARI_KHR_FRAME_ACCUMULATION",
    "ANARI_KHR_FRAME_CHANNEL_ALBEDO",
    "ANARI_KHR_FRAME_CHANNEL_INSTANCE_ID",
    "ANARI_KHR_FRAME_CHANNEL_NORMAL",
    "ANARI_KHR_FRAME_CHANNEL_OBJECT_ID",
    "ANARI_KHR_FRAME_CHANNEL_PRIMITIVE_ID",
    "ANARI_KHR_FRAME_COMPLETION_CALLBACK",
    "ANARI_KHR_GEOMETRY_CONE",
    "ANARI_KHR_GEOMETRY_CURVE",
    "ANARI_KHR_GEOMETRY_CYLINDER",
    "ANARI_KHR_GEOMETRY_QUAD",
    "ANARI_KHR_GEOMETRY_QUAD_MOTION_DEFORMATION",
    "ANARI_KHR_GEOMETRY_SPHERE",
    "ANARI_KHR_GEOMETRY_TRIANGLE",
    "ANARI_KHR_GEOMETRY_TRIANGLE_MOTION_DEFORMATION",
    "ANARI_KHR_INSTANCE_MOTION_SCALE_ROTATION_TRANSLATION",
    "ANARI_KHR_INSTANCE_MOTION_TRANSFORM",
    "ANARI_KHR_INSTANCE_TRANSFORM",
    "ANARI_KHR_INSTANCE_TRANSFORM_ARRAY",
    "ANARI_KHR_LIGHT_DIRECTIONAL",
    "ANARI_KHR_LIGHT_HDRI",
    "ANARI_KHR_LIGHT_POINT",
    "ANARI_KHR_LIGHT_PRIMARY_VISIBILITY",
    "ANARI_KHR_LIGHT_QUAD",
    "ANARI_KHR_LIGHT_RING",
    "ANARI_KHR_LIGHT_SPOT",
    "ANARI_KHR_MATERIAL_MATTE",
    "ANARI_KHR_MATERIAL_PHYSICALLY_BASED",
    "ANARI_KHR_RENDERER_AMBIENT_LIGHT",
    "ANARI_KHR_RENDERER_BACKGROUND_COLOR",
    "ANARI_KHR_RENDERER_BACKGROUND_IMAGE",
    "ANARI_KHR_RENDERER_DENOISE",
    "ANARI_KHR_SAMPLER_IMAGE1D",
    "ANARI_KHR_SAMPLER_IMAGE2D",
    "ANARI_KHR_SAMPLER_IMAGE3D",
    "ANARI_KHR_SAMPLER_IMAGExD_CLAMP_TO_BORDER",
    "ANARI_KHR_SAMPLER_PRIMITIVE",
    "ANARI_KHR_SAMPLER_TRANSFORM",
    "ANARI_PRISM_RENDERERS",
    nullptr,
};

// "default" first: it aliases the first real renderer (spec 5.3).
inline const char *kRendererSubtypes[] = {
    "default", "pathtracer", "raycast", "ao", "debug", nullptr};

} // namespace prism
