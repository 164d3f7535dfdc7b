// The eleven exported NSI C functions. Each catches everything, checks the
// context first and reports problems through the context's error handler
// (the default handler when the context itself is unknown).
#include "ContextTable.h"

#include <cmath>
#include <exception>

using prism::nsi::Context;
using prism::nsi::ContextTable;
using prism::nsi::ParameterList;

namespace {

void reportWithoutContext(const std::string &message)
{
  prism::nsi::defaultErrorHandler(nullptr, NSIErrError, 0, message.c_str());
}

// Runs `body` on the context `ctx` under its lock, catching everything.
template <typename Body>
void withContext(NSIContext_t ctx, const char *call, Body &&body)
{
  std::shared_ptr<Context> context;
  try {
    context = ContextTable::instance().find(ctx);
    if (!context) {
      reportWithoutContext(
          std::string(call) + ": unknown context " + std::to_string(ctx));
      return;
    }
    std::lock_guard lock(context->mutex);
    body(*context);
  } catch (const std::exception &e) {
    const std::string message =
        std::string(call) + ": internal error: " + e.what();
    context ? context->report(NSIErrError, message)
            : reportWithoutContext(message);
  } catch (...) {
    const std::string message = std::string(call) + ": internal error";
    context ? context->report(NSIErrError, message)
            : reportWithoutContext(message);
  }
}

// A handle or name argument; null is reported and the call skipped.
bool present(
    Context &context, const char *call, const char *what, const char *text)
{
  if (text)
    return true;
  context.report(
      NSIErrError, std::string(call) + ": no " + what + " given; ignored");
  return false;
}

// The handles and target attribute a connection needs; a null one is
// reported and the call skipped.
bool connectionNamed(Context &context,
    const char *call,
    NSIHandle_t from,
    NSIHandle_t to,
    const char *toAttr)
{
  return present(context, call, "source handle", from)
         && present(context, call, "target handle", to)
         && present(context, call, "target attribute", toAttr);
}

ParameterList params(
    Context &context, int n, const NSIParam_t *p, const char *call)
{
  return ParameterList(n, p, call, context.reporter());
}

} // namespace

extern "C" {

NSI_API NSIContext_t NSIBegin(int nparams, const NSIParam_t *params)
{
  try {
    return ContextTable::instance().add(
        [&](NSIContext_t id) -> std::shared_ptr<Context> {
          // The error handler is among the parameters: read them once without
          // reporting to find it, then for real through the new context.
          ParameterList quiet(
              nparams, params, "NSIBegin", [](int, const std::string &) {});
          auto context = std::make_shared<Context>(id, quiet);
          ParameterList(nparams, params, "NSIBegin", context->reporter());
          return context->ok() ? context : nullptr;
        });
  } catch (const std::exception &e) {
    reportWithoutContext(std::string("NSIBegin: internal error: ") + e.what());
  } catch (...) {
    reportWithoutContext("NSIBegin: internal error");
  }
  return NSI_BAD_CONTEXT;
}

NSI_API void NSIEnd(NSIContext_t ctx)
{
  try {
    auto context = ContextTable::instance().take(ctx);
    if (!context) {
      reportWithoutContext("NSIEnd: unknown context " + std::to_string(ctx));
      return;
    }
    {
      // Calls under way on other threads finish first.
      std::lock_guard lock(context->mutex);
    }
    // Stops the render; other threads' copies keep the context alive. (Not
    // under the lock: the lock dies with the context.)
    context.reset();
  } catch (...) {
    reportWithoutContext("NSIEnd: internal error");
  }
}

NSI_API void NSICreate(NSIContext_t ctx,
    NSIHandle_t handle,
    const char *type,
    int nparams,
    const NSIParam_t *p)
{
  withContext(ctx, "NSICreate", [&](Context &c) {
    if (present(c, "NSICreate", "handle", handle)
        && present(c, "NSICreate", "type", type))
      c.create(handle, type, params(c, nparams, p, "NSICreate"));
  });
}

NSI_API void NSIDelete(
    NSIContext_t ctx, NSIHandle_t handle, int nparams, const NSIParam_t *p)
{
  withContext(ctx, "NSIDelete", [&](Context &c) {
    if (present(c, "NSIDelete", "handle", handle))
      c.remove(handle, params(c, nparams, p, "NSIDelete"));
  });
}

NSI_API void NSISetAttribute(
    NSIContext_t ctx, NSIHandle_t object, int nparams, const NSIParam_t *p)
{
  withContext(ctx, "NSISetAttribute", [&](Context &c) {
    if (present(c, "NSISetAttribute", "handle", object))
      c.setAttribute(
          object, params(c, nparams, p, "NSISetAttribute"), std::nullopt);
  });
}

NSI_API void NSISetAttributeAtTime(NSIContext_t ctx,
    NSIHandle_t object,
    double time,
    int nparams,
    const NSIParam_t *p)
{
  withContext(ctx, "NSISetAttributeAtTime", [&](Context &c) {
    if (!present(c, "NSISetAttributeAtTime", "handle", object))
      return;
    // Samples are ordered by time: a NaN or infinite one has no place.
    if (!std::isfinite(time)) {
      c.report(NSIErrError,
          std::string("NSISetAttributeAtTime: time ")
              + prism::nsi::shortNumber(time) + " for '" + object
              + "' is not a finite number; ignored");
      return;
    }
    c.setAttribute(
        object, params(c, nparams, p, "NSISetAttributeAtTime"), time);
  });
}

NSI_API void NSIDeleteAttribute(
    NSIContext_t ctx, NSIHandle_t object, const char *name)
{
  withContext(ctx, "NSIDeleteAttribute", [&](Context &c) {
    if (present(c, "NSIDeleteAttribute", "handle", object)
        && present(c, "NSIDeleteAttribute", "attribute name", name))
      c.deleteAttribute(object, name);
  });
}

NSI_API void NSIConnect(NSIContext_t ctx,
    NSIHandle_t from,
    const char *from_attr,
    NSIHandle_t to,
    const char *to_attr,
    int nparams,
    const NSIParam_t *p)
{
  withContext(ctx, "NSIConnect", [&](Context &c) {
    if (connectionNamed(c, "NSIConnect", from, to, to_attr))
      c.connect(from,
          from_attr ? from_attr : "",
          to,
          to_attr,
          params(c, nparams, p, "NSIConnect"));
  });
}

NSI_API void NSIDisconnect(NSIContext_t ctx,
    NSIHandle_t from,
    const char *from_attr,
    NSIHandle_t to,
    const char *to_attr)
{
  withContext(ctx, "NSIDisconnect", [&](Context &c) {
    if (connectionNamed(c, "NSIDisconnect", from, to, to_attr))
      c.disconnect(from, from_attr ? from_attr : "", to, to_attr);
  });
}

NSI_API void NSIEvaluate(NSIContext_t ctx, int nparams, const NSIParam_t *p)
{
  withContext(ctx, "NSIEvaluate", [&](Context &c) {
    c.evaluate(params(c, nparams, p, "NSIEvaluate"));
  });
}

NSI_API void NSIRenderControl(
    NSIContext_t ctx, int nparams, const NSIParam_t *p)
{
  withContext(ctx, "NSIRenderControl", [&](Context &c) {
    c.renderControl(params(c, nparams, p, "NSIRenderControl"));
  });
}

} // extern "C"
