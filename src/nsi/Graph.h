// The node graph of one NSI context: nodes with typed attributes (a value
// and/or time samples) and connections between attributes. It only records;
// the SceneResolver reads it. Problems come back as messages, never throws.
#pragma once

#include "Value.h"

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
  int index{0}; // orders the models of an `instances` node
};

// A connection leaving one of a node's attributes.
struct Output
{
  std::string fromAttr, to, toAttr;
};

struct Node
{
  std::string type;
  std::map<std::string, Attribute> attributes;
  std::vector<Input> inputs;
  std::vector<Output> outputs;

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

  const Node *find(const std::string &handle) const;
  const std::map<std::string, Node> &nodes() const
  {
    return m_nodes;
  }

 private:
  Node *lookup(const std::string &handle, const char *call);
  bool reaches(const std::string &start, const std::string &target) const;
  void removeNode(const std::string &handle);

  Report m_report;
  std::map<std::string, Node> m_nodes;
};

} // namespace prism::nsi
