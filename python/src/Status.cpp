// Status messages: every library is loaded with one callback that hands the
// message to the Python handler (prism's logging), and remembers this
// thread's first error so raise_on_error can raise it when the call returns.
#include "Binding.h"

#include <anari/frontend/type_utility.h>

namespace prism::python {

namespace {

std::atomic<bool> g_pythonAlive{true};
std::atomic<bool> g_raiseOnError{false};
// Leaked on purpose: destroying a Python object after the interpreter has
// gone would crash at exit.
py::object *g_handler = nullptr;

struct CallErrors
{
  bool collecting{false};
  std::string firstError;
};
thread_local CallErrors t_call;

} // namespace

bool pythonAlive()
{
  return g_pythonAlive.load();
}

void beginCall()
{
  t_call.collecting = true;
  t_call.firstError.clear();
}

void endCall()
{
  t_call.collecting = false;
  if (!t_call.firstError.empty() && g_raiseOnError.load()) {
    std::string message;
    message.swap(t_call.firstError);
    throw DeviceError(message);
  }
}

void statusCallback(const void *,
    ANARIDevice,
    ANARIObject,
    ANARIDataType sourceType,
    ANARIStatusSeverity severity,
    ANARIStatusCode code,
    const char *message)
{
  if (!message || !pythonAlive())
    return;
  if (severity <= ANARI_SEVERITY_ERROR && t_call.collecting
      && t_call.firstError.empty())
    t_call.firstError = message;
  // Device threads report too: they take the GIL like any Python thread.
  py::gil_scoped_acquire gil;
  if (!g_handler || g_handler->is_none())
    return;
  try {
    (*g_handler)(
        int(severity), int(code), anari::toString(sourceType), message);
  } catch (py::error_already_set &error) {
    error.discard_as_unraisable("prism status handler");
  }
}

void bindStatus(py::module_ &m)
{
  auto anariError =
      py::register_exception<DeviceError>(m, "AnariError", PyExc_RuntimeError);
  py::register_exception<ReleasedError>(m, "ReleasedError", anariError.ptr());
  m.def(
      "set_status_handler",
      [](py::object handler) {
        if (!g_handler)
          g_handler = new py::object();
        *g_handler = std::move(handler);
      },
      "handler(severity, code, source_type_name, message) for every status "
      "message of every device");
  m.def(
      "raise_on_error",
      [](bool on) { g_raiseOnError = on; },
      "Raise AnariError when a call makes the device report an error");
  m.def("raises_on_error", [] { return g_raiseOnError.load(); });
  // atexit runs while the interpreter still works; after it, device threads
  // must leave Python alone (and shared arrays leak rather than crash).
  py::module_::import("atexit").attr("register")(
      py::cpp_function([] { g_pythonAlive = false; }));
}

} // namespace prism::python
