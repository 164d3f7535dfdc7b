#include "Resolver.h"

namespace prism::nsi {

// The highest priority wins, then the nearest, then the last connected.
// `connection`: "surfaceshader", or "volumeshader" for volumes.
const Node *Resolver::resolveShader(
    const std::vector<AttributesOnPath> &attributes,
    std::string &shaderHandle,
    const char *connection)
{
  const Node *best = nullptr;
  int bestPriority = 0, bestLevel = 0;
  for (auto &a : attributes) {
    for (const Input *input : a.node->inputsOf(connection)) {
      const Node *shader = m_graph.find(input->from);
      if (!shader)
        continue;
      const bool better =
          !best || input->priority > bestPriority
          || (input->priority == bestPriority && a.level <= bestLevel);
      if (better) {
        best = shader;
        shaderHandle = input->from;
        bestPriority = input->priority;
        bestLevel = a.level;
      }
    }
  }
  return best;
}

// An on/off attribute (visibility...) resolved by its `.priority`, then
// nearness, as 1 or 0; nullopt when none is set.
std::optional<int> Resolver::resolveFlag(
    const std::vector<AttributesOnPath> &attributes, const std::string &name)
{
  std::optional<int> result;
  double bestPriority = 0;
  int bestLevel = 0;
  for (auto &a : attributes) {
    const Value *v = a.node->attribute(name);
    if (!v)
      continue;
    const Value *p = a.node->attribute(name + ".priority");
    const double priority = p ? p->number(0) : 0;
    if (!result || priority > bestPriority
        || (priority == bestPriority && a.level <= bestLevel)) {
      const double number = v->number(1);
      result = number != 0 ? 1 : 0; // on or off is all that is read
      bestPriority = priority;
      bestLevel = a.level;
    }
  }
  return result;
}

} // namespace prism::nsi
