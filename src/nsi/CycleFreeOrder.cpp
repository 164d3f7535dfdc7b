#include "CycleFreeOrder.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

namespace prism::nsi {
namespace {

using Nodes = std::map<std::string, Node>;

// The nodes `start` reaches along outputs (`upward`) or is reached from
// along inputs, through nodes whose order lies short of `bound` (below it
// upward, above it downward); kCycle if `stop` is among them, kUnchecked
// past the search's budget.
ConnectionOrder collect(Nodes &nodes,
    Node &start,
    bool upward,
    int64_t bound,
    const Node *stop,
    std::vector<Node *> &found)
{
  std::unordered_set<const Node *> seen{&start};
  std::vector<Node *> todo{&start};
  auto reach = [&](const std::string &handle) {
    auto next = nodes.find(handle);
    if (next == nodes.end())
      return true;
    Node *n = &next->second;
    if (n == stop)
      return false;
    const bool between = upward ? n->order < bound : n->order > bound;
    if (between && seen.insert(n).second)
      todo.push_back(n);
    return true;
  };
  while (!todo.empty()) {
    if (found.size() >= kConnectionSearchBudget)
      return ConnectionOrder::kUnchecked;
    Node *at = todo.back();
    todo.pop_back();
    found.push_back(at);
    if (upward) {
      for (const Output &output : at->outputs) {
        if (!reach(output.to))
          return ConnectionOrder::kCycle;
      }
    } else {
      for (const Input &input : at->inputs)
        reach(input.from);
    }
  }
  return ConnectionOrder::kKept;
}

bool byOrder(const Node *a, const Node *b)
{
  return a->order < b->order;
}

} // namespace

ConnectionOrder orderForConnection(Nodes &nodes, Node &source, Node &target)
{
  if (&source == &target)
    return ConnectionOrder::kCycle;
  if (source.order < target.order)
    return ConnectionOrder::kKept; // already climbs
  // The target and what it reaches, down to the source's order, must rise
  // above the source and what reaches it, down to the target's order.
  std::vector<Node *> rising, sinking;
  const ConnectionOrder up =
      collect(nodes, target, true, source.order, &source, rising);
  if (up != ConnectionOrder::kKept)
    return up;
  const ConnectionOrder down =
      collect(nodes, source, false, target.order, nullptr, sinking);
  if (down != ConnectionOrder::kKept)
    return down;
  std::sort(rising.begin(), rising.end(), byOrder);
  std::sort(sinking.begin(), sinking.end(), byOrder);
  // The same orders, handed out again: sinking nodes first, each group in
  // its own order, so connections inside either group still climb.
  std::vector<int64_t> orders;
  for (const Node *n : sinking)
    orders.push_back(n->order);
  for (const Node *n : rising)
    orders.push_back(n->order);
  std::sort(orders.begin(), orders.end());
  size_t next = 0;
  for (Node *n : sinking)
    n->order = orders[next++];
  for (Node *n : rising)
    n->order = orders[next++];
  return ConnectionOrder::kKept;
}

std::vector<CycleConnection> orderAll(
    Nodes &nodes, int64_t nextOrder, const std::vector<std::string> &startFirst)
{
  // Iterative: chains may be of any depth. A connection into a node still
  // on the stack closes a cycle; every other one leads to a node that
  // finishes first, so orders by finishing time climb along them.
  enum class State { kNew, kOnStack, kDone };
  std::unordered_map<const Node *, State> state;
  std::vector<CycleConnection> cycles;
  int64_t order = nextOrder + int64_t(nodes.size()) + 1;
  struct Step
  {
    Node *node;
    const std::string *handle;
    size_t nextOutput;
  };
  std::vector<Step> stack;
  auto walkFrom = [&](Nodes::iterator start) {
    if (state[&start->second] != State::kNew)
      return;
    state[&start->second] = State::kOnStack;
    stack.push_back({&start->second, &start->first, 0});
    while (!stack.empty()) {
      Step &step = stack.back();
      if (step.nextOutput == step.node->outputs.size()) {
        step.node->order = order--;
        state[step.node] = State::kDone;
        stack.pop_back();
        continue;
      }
      const Output &output = step.node->outputs[step.nextOutput++];
      auto next = nodes.find(output.to);
      if (next == nodes.end())
        continue;
      State &seen = state[&next->second];
      if (seen == State::kOnStack) {
        cycles.push_back(
            {*step.handle, output.fromAttr, output.to, output.toAttr});
      } else if (seen == State::kNew) {
        seen = State::kOnStack;
        stack.push_back({&next->second, &next->first, 0});
      }
    }
  };
  for (const std::string &handle : startFirst) {
    auto start = nodes.find(handle);
    if (start != nodes.end())
      walkFrom(start);
  }
  for (auto start = nodes.begin(); start != nodes.end(); ++start)
    walkFrom(start);
  return cycles;
}

} // namespace prism::nsi
