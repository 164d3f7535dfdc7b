#include "Graph.h"

#include "CycleFreeOrder.h"

#include <algorithm>

namespace prism::nsi {

namespace {
const std::string kAll = NSI_ALL_NODES;

bool matches(const std::string &pattern, const std::string &name)
{
  return pattern == kAll || pattern == name;
}

bool isBuiltIn(const std::string &handle)
{
  return handle == NSI_SCENE_ROOT || handle == NSI_SCENE_GLOBAL;
}
} // namespace

const Value *Attribute::still() const
{
  if (value)
    return &*value;
  return samples.empty() ? nullptr : &samples.begin()->second;
}

const Value *Node::attribute(const std::string &name) const
{
  auto it = attributes.find(name);
  return it == attributes.end() ? nullptr : it->second.still();
}

std::vector<const Input *> Node::inputsOf(const std::string &toAttr) const
{
  std::vector<const Input *> out;
  for (auto &input : inputs) {
    if (input.toAttr == toAttr)
      out.push_back(&input);
  }
  std::sort(out.begin(), out.end(), [](const Input *a, const Input *b) {
    return a->sequence < b->sequence;
  });
  return out;
}

Graph::Graph(Report report) : m_report(std::move(report))
{
  create(NSI_SCENE_ROOT, "root");
  create(NSI_SCENE_GLOBAL, "global");
}

const Node *Graph::find(const std::string &handle) const
{
  auto it = m_nodes.find(handle);
  return it == m_nodes.end() ? nullptr : &it->second;
}

Node *Graph::lookup(const std::string &handle, const char *call)
{
  auto it = m_nodes.find(handle);
  if (it != m_nodes.end())
    return &it->second;
  m_report(NSIErrError,
      std::string(call) + ": unknown handle '" + handle + "'; ignored");
  return nullptr;
}

void Graph::create(const std::string &handle, const std::string &type)
{
  if (handle.empty() || handle == kAll) {
    m_report(NSIErrError, "NSICreate: '" + handle + "' is not a usable handle");
    return;
  }
  auto it = m_nodes.find(handle);
  if (it != m_nodes.end()) {
    // Clients share nodes by creating them again: same type is a no-op.
    if (it->second.type != type) {
      m_report(NSIErrError,
          "NSICreate: '" + handle + "' already exists as a '" + it->second.type
              + "', not a '" + type + "'");
    }
    return;
  }
  Node &node = m_nodes[handle];
  node.type = type;
  node.order = m_nextOrder--;
}

void Graph::unlink(Node &target, size_t at)
{
  Node &source = m_nodes.at(target.inputs[at].from);
  // The source's output first: the last one moves into its place.
  const size_t gap = target.inputs[at].output;
  if (gap + 1 != source.outputs.size()) {
    source.outputs[gap] = std::move(source.outputs.back());
    const Output &moved = source.outputs[gap];
    m_nodes.at(moved.to).inputs[moved.input].output = gap;
  }
  source.outputs.pop_back();
  if (at + 1 != target.inputs.size()) {
    target.inputs[at] = std::move(target.inputs.back());
    const Input &moved = target.inputs[at];
    m_nodes.at(moved.from).outputs[moved.output].input = at;
  }
  target.inputs.pop_back();
}

void Graph::removeNode(const std::string &handle)
{
  Node &node = m_nodes.at(handle);
  while (!node.inputs.empty())
    unlink(node, node.inputs.size() - 1);
  while (!node.outputs.empty()) {
    const Output &output = node.outputs.back();
    unlink(m_nodes.at(output.to), output.input);
  }
  m_nodes.erase(handle);
}

void Graph::remove(const std::string &handle, bool recursive)
{
  if (isBuiltIn(handle)) {
    m_report(NSIErrError, "NSIDelete: '" + handle + "' cannot be deleted");
    return;
  }
  if (!lookup(handle, "NSIDelete"))
    return;
  // A worklist, not recursion: a recursive delete may run down a chain of
  // any depth.
  std::vector<std::string> todo{handle};
  while (!todo.empty()) {
    const std::string at = std::move(todo.back());
    todo.pop_back();
    const Node *node = find(at);
    if (!node)
      continue; // reached twice, already gone
    std::vector<std::string> sources;
    for (auto &input : node->inputs) {
      if (input.strength <= 0)
        sources.push_back(input.from);
    }
    removeNode(at);
    if (!recursive)
      return;
    // A source goes too once nothing else uses it (strong links protect it).
    for (auto &source : sources) {
      const Node *s = find(source);
      if (s && s->outputs.empty() && !isBuiltIn(source))
        todo.push_back(source);
    }
  }
}

void Graph::setAttribute(const std::string &handle,
    const std::string &name,
    const Value &value,
    std::optional<double> time)
{
  Node *node =
      lookup(handle, time ? "NSISetAttributeAtTime" : "NSISetAttribute");
  if (!node)
    return;
  Attribute &attribute = node->attributes[name];
  if (time) {
    attribute.samples[*time] = value;
  } else {
    attribute.value = value;
    attribute.samples.clear();
  }
}

void Graph::deleteAttribute(const std::string &handle, const std::string &name)
{
  if (Node *node = lookup(handle, "NSIDeleteAttribute"))
    node->attributes.erase(name);
}

Input *Graph::existingInput(const Node &source,
    Node &target,
    const std::string &from,
    const std::string &fromAttr,
    const std::string &to,
    const std::string &toAttr)
{
  auto sameInput = [&](const Input &input) {
    return input.from == from && input.fromAttr == fromAttr
           && input.toAttr == toAttr;
  };
  // A node may have a million connections on one side (.root's objects,
  // a shared material's outputs) and a few on the other.
  if (source.outputs.size() < target.inputs.size()) {
    auto it = std::find_if(
        source.outputs.begin(), source.outputs.end(), [&](const Output &o) {
          return o.to == to && o.fromAttr == fromAttr && o.toAttr == toAttr;
        });
    return it == source.outputs.end() ? nullptr : &target.inputs[it->input];
  }
  auto it = std::find_if(target.inputs.begin(), target.inputs.end(), sameInput);
  return it == target.inputs.end() ? nullptr : &*it;
}

void Graph::connect(const std::string &from,
    const std::string &fromAttr,
    const std::string &to,
    const std::string &toAttr,
    int priority,
    int strength,
    int index)
{
  Node *source = lookup(from, "NSIConnect");
  Node *target = lookup(to, "NSIConnect");
  if (!source || !target)
    return;
  if (Input *input =
          existingInput(*source, *target, from, fromAttr, to, toAttr)) {
    input->priority = priority; // connecting again updates, never duplicates
    input->strength = strength;
    input->index = index;
    return;
  }
  if (!m_unchecked) {
    const ConnectionOrder order = orderForConnection(m_nodes, *source, *target);
    if (order == ConnectionOrder::kCycle) {
      m_report(NSIErrError,
          "NSIConnect: '" + from + "' -> '" + to + "." + toAttr
              + "' would close a cycle; ignored");
      return;
    }
    m_unchecked = order == ConnectionOrder::kUnchecked;
  }
  if (m_unchecked)
    m_uncheckedTargets.push_back(to);
  const size_t input = target->inputs.size(), output = source->outputs.size();
  target->inputs.push_back({from,
      fromAttr,
      toAttr,
      priority,
      strength,
      index,
      m_nextSequence++,
      output});
  source->outputs.push_back({fromAttr, to, toAttr, input});
}

void Graph::checkCycles()
{
  if (!m_unchecked)
    return;
  m_unchecked = false;
  // Newest first: a walk from the target of the connection that closed a
  // cycle meets that very connection as the one going back.
  const std::vector<std::string> startFirst(
      m_uncheckedTargets.rbegin(), m_uncheckedTargets.rend());
  m_uncheckedTargets.clear();
  for (const CycleConnection &c : orderAll(m_nodes, m_nextOrder, startFirst)) {
    m_report(NSIErrError,
        "NSIConnect: '" + c.from + "' -> '" + c.to + "." + c.toAttr
            + "' closed a cycle; removed when the render started");
    disconnect(c.from, c.fromAttr, c.to, c.toAttr);
  }
}

void Graph::disconnect(const std::string &from,
    const std::string &fromAttr,
    const std::string &to,
    const std::string &toAttr)
{
  Node *source = from == kAll ? nullptr : lookup(from, "NSIDisconnect");
  if (from != kAll && !source)
    return;
  Node *target = to == kAll ? nullptr : lookup(to, "NSIDisconnect");
  if (to != kAll && !target)
    return;
  // Whichever end is named and has fewer connections is searched. From the
  // back: a removal moves the last connection, already looked at, into the
  // gap.
  if (source && (!target || source->outputs.size() < target->inputs.size())) {
    for (size_t at = source->outputs.size(); at-- > 0;) {
      const Output &output = source->outputs[at];
      if (matches(to, output.to) && matches(fromAttr, output.fromAttr)
          && matches(toAttr, output.toAttr))
        unlink(m_nodes.at(output.to), output.input);
    }
    return;
  }
  auto unlinkMatches = [&](Node &node) {
    for (size_t at = node.inputs.size(); at-- > 0;) {
      const Input &input = node.inputs[at];
      if (matches(from, input.from) && matches(fromAttr, input.fromAttr)
          && matches(toAttr, input.toAttr))
        unlink(node, at);
    }
  };
  if (target) {
    unlinkMatches(*target);
    return;
  }
  for (auto &entry : m_nodes)
    unlinkMatches(entry.second);
}

} // namespace prism::nsi
