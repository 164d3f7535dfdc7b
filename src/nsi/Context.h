// One NSI context: its node graph (or, for `type apistream`, the stream the
// calls are written to), its error handler and its render. The API entry
// points lock it, so one context may be used from several threads.
#pragma once

#include "DynamicProcedurals.h"
#include "Graph.h"
#include "ParameterList.h"
#include "RenderSession.h"
#include "StreamWriter.h"

#include <map>
#include <memory>
#include <mutex>
#include <set>

namespace prism::nsi {

class Context
{
 public:
  // Reads NSIBegin's parameters; ok() tells whether the context is usable.
  Context(NSIContext_t id, const ParameterList &params);
  ~Context();

  bool ok() const
  {
    return m_ok;
  }
  void report(int level, const std::string &message) const;
  ReportFunction reporter() const;
  // The node graph, for loaders that resolve it themselves (scene-io).
  const Graph &graph() const
  {
    return m_graph;
  }

  // Re-entrant: an included stream calls back into the API on this thread.
  std::recursive_mutex mutex;

  void create(const std::string &handle,
      const std::string &type,
      const ParameterList &params);
  void remove(const std::string &handle, const ParameterList &params);
  void setAttribute(const std::string &handle,
      const ParameterList &params,
      std::optional<double> time);
  void deleteAttribute(const std::string &handle, const std::string &name);
  void connect(const std::string &from,
      const std::string &fromAttr,
      const std::string &to,
      const std::string &toAttr,
      const ParameterList &params);
  void disconnect(const std::string &from,
      const std::string &fromAttr,
      const std::string &to,
      const std::string &toAttr);
  void evaluate(const ParameterList &params);
  void renderControl(const ParameterList &params);

 private:
  void includeStream(const std::string &fileName);
  // Runs the procedural nodes whose attributes changed since they last ran
  // (first deleting what that run made), and forgets the deleted ones'.
  void runProceduralNodes();
  void removeNodes(const std::vector<std::string> &handles);
  // `handle`, or the running procedural node for .root.
  const std::string &localRoot(const std::string &handle) const;
  // `synchronizing`: the render's completion is reported as
  // NSIRenderSynchronized.
  void startRender(const ParameterList &params, bool synchronizing = false);
  void synchronize(const ParameterList &params);
  // The stopped callback for a render (the one given in `params`, else the
  // last one); when `synchronizing`, completion reads NSIRenderSynchronized.
  RenderSession::Stopped stoppedCallback(
      const ParameterList &params, bool synchronizing);
  // Waits for (or stops) the render without holding the context lock, so
  // other threads and the stopped callback can use the context meanwhile.
  void finishRender(bool stop);

  NSIContext_t m_id;
  bool m_ok{true};
  NSIErrorHandler_t m_errorHandler{nullptr};
  void *m_errorHandlerData{nullptr};
  std::string m_anariLibrary{"prism"};
  Graph m_graph;
  std::unique_ptr<StreamWriter> m_writer; // set for `type apistream`
  // Loaded at the first dynamiclibrary Evaluate; unloaded at NSIEnd.
  std::unique_ptr<DynamicProcedurals> m_procedurals;
  // Shared so a thread waiting without the lock keeps it alive.
  std::shared_ptr<RenderSession> m_render;
  RenderSession::Stopped m_stopped;    // the last stoppedcallback given
  std::set<std::string> m_openStreams; // includes being read, against cycles
  // Per procedural node: the attributes it last ran with, the nodes it made.
  struct ProceduralRun
  {
    std::vector<NamedValue> attributes;
    std::vector<std::string> created;
  };
  std::map<std::string, ProceduralRun> m_proceduralRuns;
  // While a procedural node runs: its handle stands for .root, and the
  // nodes created are recorded.
  std::string m_localRoot;
  std::vector<std::string> *m_created{nullptr};
  // Evaluate types a stream-writing context runs rather than records.
  std::set<std::string> m_executedTypes;
};

// Prints to stderr with the level, as NSI's default handler does.
void defaultErrorHandler(
    void *userdata, int level, int code, const char *message);

} // namespace prism::nsi
