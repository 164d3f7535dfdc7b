// The API revision these headers implement: binary compatible with the
// Khronos ANARI-SDK 0.17 (see docs/ABI.md).
#pragma once

#define ANARI_SDK_VERSION_MAJOR 0
#define ANARI_SDK_VERSION_MINOR 17
#define ANARI_SDK_VERSION_PATCH 0
#define ANARI_SDK_VERSION "0.17.0"
