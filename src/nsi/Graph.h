// The node graph of one NSI context: nodes with typed attributes (a value
// and/or time samples) and connections between attributes. It only records;
// the SceneResolver reads it. Problems come back as messages, never throws.
#pragma once

#include "Value.h"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace prism::nsi {

struct Attribute
{
  std::optional<Value> value;      // from SetAttribute
  std::map<double, Value> samples; // from SetAttributeAtTime, by time

  // The value to use for a still image: the plain value, else the first sample.
  const Value *still() const;
};

// A connection arriving at one of a node's attributes.
struct Input
{
  std::string from, fromAttr, toAttr;
  int priority{0};
  int strength{0};
  int index{0};         // orders the models of an `instances` node
  uint64_t sequence{0}; // when it was first connected (inputsOf's order)
  size_t output{0};     // its Output's place in the source's outputs
};

// A connection leaving one of a node's attributes.
struct Output
{
  std::string fromAttr, to, toAttr;
  size_t input{0}; // its Input's place in the target's inputs
};

struct Node
{
  std::string type;
  std::map<std::string, Attribute> attributes;
  // In no order (a removal moves the last one into the gap, so removing a
  // connection costs the same at a node with a million); each side knows
  // where its other side is.
  std::vector<Input> inputs;
  std::vector<Output> outputs;
  // Place in an order every connection follows (a source lies below what it
  // connects into), kept up to date by Graph::connect: see
  // CycleFreeOrder.h.
  int64_t order{0};

  const Value *attribute(const std::string &name) const;
  // The nodes connected into `toAttr`, in connection order.
  std::vector<const Input *> inputsOf(const std::string &toAttr) const;
};

class Graph
{
 public:
  using Report = std::function<void(int level, const std::string &)>;

  explicit Graph(Report report);

  void create(const std::string &handle, const std::string &type);
  void remove(const std::string &handle, bool recursive);
  void setAttribute(const std::string &handle,
      const std::string &name,
      const Value &value,
      std::optional<double> time);
  void deleteAttribute(const std::string &handle, const std::string &name);
  void connect(const std::string &from,
      const std::string &fromAttr,
      const std::string &to,
      const std::string &toAttr,
      int priority,
      int strength,
      int index = 0);
  void disconnect(const std::string &from,
      const std::string &fromAttr,
      const std::string &to,
      const std::string &toAttr);

  // Checks the connections taken unchecked since the last call (a search
  // for a cycle past its budget), removing and reporting any that closed
  // one: called before the scene is resolved.
  void checkCycles();

  const Node *find(const std::string &handle) const;
  const std::map<std::string, Node> &nodes() const
  {
    return m_nodes;
  }

 private:
  Node *lookup(const std::string &handle, const char *call);
  void removeNode(const std::string &handle);
  // Removes `target`'s input at `at` and its output at the source.
  void unlink(Node &target, size_t at);
  // The connection from `source` to `target` made again (nullptr if new),
  // searched where the two nodes have fewer connections.
  Input *existingInput(const Node &source,
      Node &target,
      const std::string &from,
      const std::string &fromAttr,
      const std::string &to,
      const std::string &toAttr);

  Report m_report;
  std::map<std::string, Node> m_nodes;
  // New nodes go below every other: a scene made parents first, as scenes
  // are, never needs reordering.
  int64_t m_nextOrder{0};
  uint64_t m_nextSequence{0};
  // Connections were taken without a cycle check; orders may not climb.
  bool m_unchecked{false};
  std::vector<std::string> m_uncheckedTargets; // in connection order
};

} // namespace prism::nsi
