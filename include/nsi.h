/* The Nodal Scene Interface, C API (NSI_VERSION 2), as implemented by Prism's
   libnsi. Values and the NSIParam_t layout match the public header so that
   clients built against it run unchanged. */
#ifndef PRISM_NSI_H
#define PRISM_NSI_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(_WIN32)
#define NSI_API __declspec(dllimport)
#else
#define NSI_API __attribute__((visibility("default")))
#endif

#define NSI_VERSION 2

typedef int NSIContext_t; /* 0 means failure */
typedef const char *NSIHandle_t;

#define NSI_BAD_CONTEXT ((NSIContext_t)0)
#define NSI_SCENE_ROOT ".root"
#define NSI_SCENE_GLOBAL ".global"
#define NSI_ALL_NODES ".all"
#define NSI_ALL_ATTRIBUTES ".all"

enum NSIType_t {
  NSITypeInvalid = 0,
  NSITypeFloat = 1,
  NSITypeInteger = 2,
  NSITypeString = 3,
  NSITypeColor = 4,
  NSITypePoint = 5,
  NSITypeVector = 6,
  NSITypeNormal = 7,
  NSITypeMatrix = 8,
  NSITypePointer = 9,
  NSITypeHPoint = 10,
  NSITypeDouble = 0x11, /* 0x10 marks the 64-bit forms */
  NSITypeInt64 = 0x12,
  NSITypeDoubleMatrix = 0x18
};

enum {
  NSIParamIsArray = 1,
  NSIParamPerFace = 2,
  NSIParamPerVertex = 4,
  NSIParamInterpolateLinear = 8
};

struct NSIParam_t
{
  const char *name;
  const void *data; /* points at the values (strings: at const char *s) */
  int type;
  int arraylength;
  size_t count;
  int flags;
};
typedef struct NSIParam_t NSIParam_t;

#if defined(__LP64__) && !defined(__cplusplus)
/* C99 has no static_assert: a negative array size stops the build. */
typedef char
    NSIParamLayoutCheck_t[(sizeof(struct NSIParam_t) == 40
                              && offsetof(struct NSIParam_t, type) == 16
                              && offsetof(struct NSIParam_t, count) == 24
                              && offsetof(struct NSIParam_t, flags) == 32)
                              ? 1
                              : -1];
#elif defined(__LP64__)
static_assert(sizeof(struct NSIParam_t) == 40, "NSIParam_t is 40 bytes");
static_assert(offsetof(struct NSIParam_t, name) == 0, "name at 0");
static_assert(offsetof(struct NSIParam_t, data) == 8, "data at 8");
static_assert(offsetof(struct NSIParam_t, type) == 16, "type at 16");
static_assert(offsetof(struct NSIParam_t, arraylength) == 20, "arraylength");
static_assert(offsetof(struct NSIParam_t, count) == 24, "count at 24");
static_assert(offsetof(struct NSIParam_t, flags) == 32, "flags at 32");
#endif

enum NSIStoppingStatus {
  NSIRenderCompleted = 0,
  NSIRenderAborted = 1,
  NSIRenderSynchronized = 2,
  NSIRenderRestarted = 3
};

enum NSIErrorLevel {
  NSIErrMessage = 0,
  NSIErrInfo = 1,
  NSIErrWarning = 2,
  NSIErrError = 3
};
/* The specification's spelling. */
#define NSIErrorMessage NSIErrMessage

typedef void (*NSIErrorHandler_t)(
    void *userdata, int level, int code, const char *message);
typedef void (*NSIRenderStopped_t)(
    void *userdata, NSIContext_t ctx, int status);

/* Bytes of one value of `type` (0 for unknown types). */
static inline size_t NSITypeSizeOf(unsigned type)
{
  switch (type) {
  case NSITypeFloat:
  case NSITypeInteger:
    return 4;
  case NSITypeString:
    return sizeof(char *);
  case NSITypeColor:
  case NSITypePoint:
  case NSITypeVector:
  case NSITypeNormal:
    return 12;
  case NSITypeMatrix:
    return 64;
  case NSITypePointer:
    return sizeof(void *);
  case NSITypeHPoint:
    return 16;
  case NSITypeDouble:
  case NSITypeInt64:
    return 8;
  case NSITypeDoubleMatrix:
    return 128;
  default:
    return 0;
  }
}

NSI_API NSIContext_t NSIBegin(int nparams, const struct NSIParam_t *params);
NSI_API void NSIEnd(NSIContext_t ctx);
NSI_API void NSICreate(NSIContext_t ctx,
    NSIHandle_t handle,
    const char *type,
    int nparams,
    const struct NSIParam_t *params);
NSI_API void NSIDelete(NSIContext_t ctx,
    NSIHandle_t handle,
    int nparams,
    const struct NSIParam_t *params);
NSI_API void NSISetAttribute(NSIContext_t ctx,
    NSIHandle_t object,
    int nparams,
    const struct NSIParam_t *params);
NSI_API void NSISetAttributeAtTime(NSIContext_t ctx,
    NSIHandle_t object,
    double time,
    int nparams,
    const struct NSIParam_t *params);
NSI_API void NSIDeleteAttribute(
    NSIContext_t ctx, NSIHandle_t object, const char *name);
NSI_API void NSIConnect(NSIContext_t ctx,
    NSIHandle_t from,
    const char *from_attr,
    NSIHandle_t to,
    const char *to_attr,
    int nparams,
    const struct NSIParam_t *params);
NSI_API void NSIDisconnect(NSIContext_t ctx,
    NSIHandle_t from,
    const char *from_attr,
    NSIHandle_t to,
    const char *to_attr);
NSI_API void NSIEvaluate(
    NSIContext_t ctx, int nparams, const struct NSIParam_t *params);
NSI_API void NSIRenderControl(
    NSIContext_t ctx, int nparams, const struct NSIParam_t *params);

#ifdef __cplusplus
}
#endif

#endif
