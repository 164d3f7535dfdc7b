#include "Context.h"

#include "LuaScript.h"
#include "PathExpansion.h"
#include "SceneResolver.h"
#include "StreamReader.h"
#include "StreamSource.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <utility>

namespace prism::nsi {

void defaultErrorHandler(void *, int level, int, const char *message)
{
  const char *prefix = level >= NSIErrError     ? "error: "
                       : level == NSIErrWarning ? "warning: "
                       : level == NSIErrInfo    ? "info: "
                                                : "";
  // Plain messages are printed as given, with no newline added.
  std::fprintf(stderr,
      "%s%s%s",
      prefix,
      message ? message : "",
      level == NSIErrMessage ? "" : "\n");
}

Context::Context(NSIContext_t id, const ParameterList &params)
    : m_id(id), m_graph([this](int level, const std::string &message) {
        report(level, message);
      })
{
  m_errorHandler =
      reinterpret_cast<NSIErrorHandler_t>(params.pointer("errorhandler"));
  m_errorHandlerData = params.pointer("errorhandlerdata");
  if (const char *library = std::getenv("PRISM_NSI_ANARI_LIBRARY");
      library && *library)
    m_anariLibrary = library;
  m_anariLibrary = params.string("anarilibrary", m_anariLibrary);

  const std::string type = params.string("type", "render");
  if (type == "apistream") {
    const std::string target = params.string("streamfilename", "stdout");
    const std::string format = params.string("streamformat", "nsi");
    if (format != "nsi" && format != "autonsi")
      report(NSIErrWarning,
          "NSIBegin: stream format '" + format
              + "' is not supported; writing the ASCII format");
    const std::string compression = params.string("streamcompression", "");
    if (!compression.empty() && compression != "gzip")
      report(NSIErrWarning,
          "NSIBegin: stream compression '" + compression
              + "' is not supported; writing plain text");
    // "apistream" here makes included streams inline into the written one.
    std::string types = params.string("executeprocedurals", "");
    for (char &c : types)
      c = c == ',' ? ' ' : c;
    std::istringstream names(types);
    for (std::string name; names >> name;)
      m_executedTypes.insert(name);
    m_writer = std::make_unique<StreamWriter>(target, compression == "gzip");
    if (!m_writer->ok()) {
      report(NSIErrError, "NSIBegin: cannot write the stream '" + target + "'");
      m_ok = false;
    }
  } else if (type != "render") {
    report(NSIErrError, "NSIBegin: unknown context type '" + type + "'");
    m_ok = false;
  }
}

Context::~Context()
{
  if (m_render)
    m_render->close();   // the render thread reports through this context
  m_procedurals.reset(); // unloaded while the context still reports
}

void Context::report(int level, const std::string &message) const
{
  NSIErrorHandler_t handler =
      m_errorHandler ? m_errorHandler : defaultErrorHandler;
  handler(m_errorHandlerData, level, 0, message.c_str());
}

ReportFunction Context::reporter() const
{
  return [this](int level, const std::string &message) {
    report(level, message);
  };
}

void Context::create(const std::string &handle,
    const std::string &type,
    const ParameterList &params)
{
  if (m_writer)
    return m_writer->statement("Create", {handle, type}, params);
  if (m_created && !m_graph.find(handle))
    m_created->push_back(handle);
  m_graph.create(handle, type);
}

void Context::remove(const std::string &handle, const ParameterList &params)
{
  if (m_writer)
    return m_writer->statement("Delete", {handle}, params);
  m_graph.remove(handle, params.number("recursive", 0) != 0);
}

void Context::setAttribute(const std::string &handle,
    const ParameterList &params,
    std::optional<double> time)
{
  if (m_writer)
    return m_writer->statement(
        time ? "SetAttributeAtTime" : "SetAttribute", {handle}, params, time);
  for (auto &param : params.values)
    m_graph.setAttribute(handle, param.name, param.value, time);
}

void Context::deleteAttribute(
    const std::string &handle, const std::string &name)
{
  if (m_writer)
    return m_writer->statement("DeleteAttribute", {handle, name}, {});
  m_graph.deleteAttribute(handle, name);
}

namespace {
// An int connection parameter; 0 when absent or not a sane number.
int connectionInt(const ParameterList &params, const char *name)
{
  const double value = params.number(name, 0);
  return std::isfinite(value) && std::abs(value) < 1e9 ? int(value) : 0;
}
} // namespace

void Context::connect(const std::string &from,
    const std::string &fromAttr,
    const std::string &to,
    const std::string &toAttr,
    const ParameterList &params)
{
  if (m_writer)
    return m_writer->statement("Connect", {from, fromAttr, to, toAttr}, params);
  // The spec's use of a connection's value is a cross-hierarchy override
  // (an attribute seen differently by rays from one object); ANARI has no
  // per-ray-origin attributes, so the connection is kept without it.
  if (params.find("value"))
    report(NSIErrWarning,
        "NSIConnect '" + from + "' to '" + to + "'.'" + toAttr
            + "': 'value' overrides are not supported; connected without "
              "it");
  m_graph.connect(from,
      fromAttr,
      localRoot(to),
      toAttr,
      connectionInt(params, "priority"),
      connectionInt(params, "strength"),
      connectionInt(params, "index"));
}

void Context::disconnect(const std::string &from,
    const std::string &fromAttr,
    const std::string &to,
    const std::string &toAttr)
{
  if (m_writer)
    return m_writer->statement("Disconnect", {from, fromAttr, to, toAttr}, {});
  m_graph.disconnect(from, fromAttr, localRoot(to), toAttr);
}

void Context::evaluate(const ParameterList &params)
{
  const std::string type = params.string("type", "");
  if (m_writer && !m_executedTypes.count(type))
    return m_writer->statement("Evaluate", {}, params);
  if (type == "apistream") {
    const std::string fileName = params.string("filename", "");
    if (fileName.empty()) {
      report(NSIErrError, "NSIEvaluate: 'apistream' without a 'filename'");
      return;
    }
    includeStream(expandPath(fileName));
  } else if (type == "lua") {
    const std::string fileName = params.string("filename", "");
    runLua(
        m_id, reporter(), params, fileName.empty() ? "" : expandPath(fileName));
  } else if (type == "dynamiclibrary") {
    const std::string fileName = params.string("filename", "");
    if (fileName.empty()) {
      report(NSIErrError, "NSIEvaluate: 'dynamiclibrary' without a 'filename'");
      return;
    }
    if (!m_procedurals)
      m_procedurals = std::make_unique<DynamicProcedurals>(m_id, reporter());
    m_procedurals->execute(expandPath(fileName), params);
  } else {
    report(NSIErrError, "NSIEvaluate: unknown type '" + type + "'");
  }
}

void Context::includeStream(const std::string &fileName)
{
  std::error_code error;
  std::string key = std::filesystem::weakly_canonical(fileName, error).string();
  if (error)
    key = fileName;
  if (m_openStreams.count(key)) {
    report(NSIErrError,
        "NSIEvaluate: '" + fileName + "' includes itself; not read again");
    return;
  }
  std::string text, why;
  if (!readStreamText(fileName, text, why)) {
    report(NSIErrError, "NSIEvaluate: cannot read '" + fileName + "': " + why);
    return;
  }
  // Open while read, however the reading ends.
  struct OpenStream
  {
    std::set<std::string> &open;
    std::string key;
    ~OpenStream()
    {
      open.erase(key);
    }
  } guard{m_openStreams, key};
  m_openStreams.insert(key);
  StreamReader(m_id, reporter(), fileName).read(text);
}

const std::string &Context::localRoot(const std::string &handle) const
{
  return handle == NSI_SCENE_ROOT && !m_localRoot.empty() ? m_localRoot
                                                          : handle;
}

void Context::removeNodes(const std::vector<std::string> &handles)
{
  for (auto &handle : handles) {
    if (m_graph.find(handle)) // the client may have deleted it
      m_graph.remove(handle, false);
  }
}

void Context::runProceduralNodes()
{
  for (auto it = m_proceduralRuns.begin(); it != m_proceduralRuns.end();) {
    const Node *node = m_graph.find(it->first);
    if (node && node->type == "procedural") {
      ++it;
      continue;
    }
    removeNodes(it->second.created);
    it = m_proceduralRuns.erase(it);
  }
  std::vector<std::pair<std::string, ParameterList>> due;
  for (auto &[handle, node] : m_graph.nodes()) {
    if (node.type != "procedural")
      continue;
    ParameterList params;
    for (auto &[name, attribute] : node.attributes) {
      if (attribute.value)
        params.values.push_back({name, *attribute.value});
    }
    auto found = m_proceduralRuns.find(handle);
    if (found == m_proceduralRuns.end()
        || found->second.attributes != params.values)
      due.emplace_back(handle, std::move(params));
  }
  for (auto &[handle, params] : due) {
    ProceduralRun &run = m_proceduralRuns[handle];
    removeNodes(run.created);
    run = {params.values, {}};
    // One level deep: what a procedural's procedural nodes make runs at
    // the next start or synchronize.
    const std::string outerRoot = std::exchange(m_localRoot, handle);
    auto *outerCreated = std::exchange(m_created, &run.created);
    evaluate(params);
    m_localRoot = outerRoot;
    m_created = outerCreated;
  }
}

void Context::renderControl(const ParameterList &params)
{
  if (m_writer)
    return m_writer->statement("RenderControl", {}, params);
  const std::string action = params.string("action", "");
  if (action == "start") {
    startRender(params);
  } else if (action == "wait") {
    finishRender(false);
  } else if (action == "synchronize") {
    synchronize(params);
  } else if (action == "stop") {
    finishRender(true);
  } else if (action == "suspend" || action == "resume") {
    if (!m_render || !m_render->running())
      report(NSIErrInfo,
          "NSIRenderControl: '" + action + "' with no render running");
    else if (action == "suspend")
      m_render->suspend();
    else
      m_render->resume();
  } else {
    report(NSIErrError, "NSIRenderControl: unknown action '" + action + "'");
  }
}

void Context::finishRender(bool stop)
{
  std::shared_ptr<RenderSession> render = m_render;
  if (!render)
    return;
  mutex.unlock();
  RenderSession::Waited waited = RenderSession::Waited::kEnded;
  if (stop)
    render->stop();
  else
    waited = render->wait();
  mutex.lock();
  if (waited == RenderSession::Waited::kSuspended) {
    report(NSIErrWarning,
        "NSIRenderControl: 'wait' on a suspended render returns at once (it "
        "would never end); 'resume' or 'stop' it");
  } else if (waited == RenderSession::Waited::kOnRenderThread) {
    report(NSIErrWarning,
        "NSIRenderControl: 'wait' from the render's own callback returns at "
        "once (the render ends after the callback)");
  }
}

RenderSession::Stopped Context::stoppedCallback(
    const ParameterList &params, bool synchronizing)
{
  // The callback stays with the context until another is given.
  auto callback =
      reinterpret_cast<NSIRenderStopped_t>(params.pointer("stoppedcallback"));
  void *callbackData = params.pointer("stoppedcallbackdata");
  const NSIContext_t id = m_id;
  if (callback) {
    m_stopped = [callback, callbackData, id](int status) {
      callback(callbackData, id, status);
    };
  }
  if (!synchronizing || !m_stopped)
    return m_stopped;
  return [report = m_stopped](int status) {
    report(status == NSIRenderCompleted ? NSIRenderSynchronized : status);
  };
}

void Context::synchronize(const ParameterList &params)
{
  // A render under way is restarted (and says so); the new one ends
  // "synchronized". The ANARI objects of the last render are kept, and only
  // those the edits touch are updated.
  const bool wasRunning = m_render && m_render->running();
  if (m_render)
    m_render->silenceStopped();
  finishRender(true);
  if (wasRunning && m_stopped)
    m_stopped(NSIRenderRestarted);
  if (!m_render || !m_render->hasDevice())
    return startRender(params, true);
  if (m_render->running()) { // another thread started one meanwhile
    report(NSIErrError,
        "NSIRenderControl: 'synchronize' while a render is starting; "
        "ignored");
    return;
  }
  runProceduralNodes();
  m_graph.checkCycles();
  const ResolvedScene scene = resolveScene(m_graph, reporter(), expandPath);
  m_render->synchronize(scene, stoppedCallback(params, true));
  report(NSIErrInfo,
      "NSIRenderControl: synchronize updated the ANARI objects: "
          + m_render->counts().summary());
}

void Context::startRender(const ParameterList &params, bool synchronizing)
{
  if (m_render && m_render->running()) {
    report(NSIErrError,
        "NSIRenderControl: 'start' while a render is running; ignored");
    return;
  }
  const RenderSession::Stopped stopped = stoppedCallback(params, synchronizing);
  runProceduralNodes();
  m_graph.checkCycles();
  const ResolvedScene scene = resolveScene(m_graph, reporter(), expandPath);
  m_render = std::make_shared<RenderSession>(reporter(), stopped);
  // Interactive renders are progressive too (NSI says so).
  const bool progressive = params.number("progressive", 0) != 0
                           || params.number("interactive", 0) != 0;
  if (!m_render->start(m_anariLibrary, scene, progressive))
    m_render.reset();
}

} // namespace prism::nsi
