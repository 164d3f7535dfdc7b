// Cycle detection for NSIConnect in time that does not grow with the graph:
// every node holds an order (Node::order) that every connection climbs
// (source below target). A connection that already climbs costs nothing;
// one that descends searches only the nodes whose order lies between its
// ends (the dynamic topological order of Pearce and Kelly) and either finds
// the cycle it would close or moves those nodes so the order holds again.
// That search has a budget: past it (a long chain connected against its
// creation order) the connection is taken unchecked, and the graph checks
// and reorders everything once, in one pass, when a render starts
// (orderAll), reporting and removing any connection that closed a cycle.
#pragma once

#include "Graph.h"

namespace prism::nsi {

enum class ConnectionOrder {
  kKept,      // the connection climbs (the nodes between were reordered)
  kCycle,     // it would close a cycle
  kUnchecked, // the search ran past its budget: check at the next render
};

// Nodes a connection's search may visit before it gives up.
constexpr size_t kConnectionSearchBudget = 1024;

// Whether connecting `source` into `target` keeps the graph free of
// cycles, reordering the nodes between them when it does.
ConnectionOrder orderForConnection(
    std::map<std::string, Node> &nodes, Node &source, Node &target);

// A connection that closed a cycle, found by orderAll.
struct CycleConnection
{
  std::string from, fromAttr, to, toAttr;
};

// One depth-first pass over the whole graph: every node gets an order all
// connections climb, once the connections returned (those that closed a
// cycle) are removed. Orders end above `nextOrder`. The walk starts from
// `startFirst` (the targets of the unchecked connections, newest first),
// so the connection reported for a cycle is the one that closed it.
std::vector<CycleConnection> orderAll(std::map<std::string, Node> &nodes,
    int64_t nextOrder,
    const std::vector<std::string> &startFirst);

} // namespace prism::nsi
