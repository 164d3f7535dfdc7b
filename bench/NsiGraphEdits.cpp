// NSI graph edits at scale: the time to build a transform chain of growing
// depth (parents created first; leaves created first and connected from
// the leaf up, the order the cycle check repairs most) and to hang a
// growing number of meshes flat under .root (and to delete them one by
// one), through libnsi's C API. The time per node should not grow with the
// graph (each NSIConnect's cycle check once walked everything its target
// reached; each delete scanned .root's inputs).
#include <nsi.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace {

void quiet(void *, int, int, const char *) {}

// A render context whose ANARI library does not exist: `start` orders
// and resolves the graph, then renders nothing.
NSIContext_t beginContext()
{
  const void *handler = reinterpret_cast<const void *>(&quiet);
  const char *library = "prism-bench-no-such-library";
  NSIParam_t params[] = {
      {"errorhandler", &handler, NSITypePointer, 0, 1, 0},
      {"anarilibrary", &library, NSITypeString, 0, 1, 0},
  };
  return NSIBegin(2, params);
}

// `start`: what a render does to the graph before it loads the library.
void start(NSIContext_t ctx)
{
  const char *action = "start";
  NSIParam_t param{"action", &action, NSITypeString, 0, 1, 0};
  NSIRenderControl(ctx, 1, &param);
}

std::string numbered(const char *prefix, int number)
{
  std::string text = prefix;
  return text.append(std::to_string(number));
}

void chain(NSIContext_t ctx, int depth, bool parentsFirst)
{
  for (int i = 0; i < depth; ++i) {
    const int level = parentsFirst ? i : depth - 1 - i;
    NSICreate(ctx, numbered("t", level).c_str(), "transform", 0, nullptr);
  }
  NSIConnect(ctx, "t0", "", NSI_SCENE_ROOT, "objects", 0, nullptr);
  for (int i = 1; i < depth; ++i) {
    const int level = parentsFirst ? i : depth - i;
    NSIConnect(ctx,
        numbered("t", level).c_str(),
        "",
        numbered("t", level - 1).c_str(),
        "objects",
        0,
        nullptr);
  }
}

void flat(NSIContext_t ctx, int nodes)
{
  for (int i = 0; i < nodes; ++i) {
    const std::string handle = numbered("m", i);
    NSICreate(ctx, handle.c_str(), "mesh", 0, nullptr);
    NSIConnect(ctx, handle.c_str(), "", NSI_SCENE_ROOT, "objects", 0, nullptr);
  }
}

void flatThenDeleted(NSIContext_t ctx, int nodes)
{
  flat(ctx, nodes);
  for (int i = 0; i < nodes; ++i)
    NSIDelete(ctx, numbered("m", i).c_str(), 0, nullptr);
}

// Seconds to build with `build(ctx, size)` in a fresh context (its end,
// which frees the graph, not counted).
double secondsToBuild(
    const std::function<void(NSIContext_t, int)> &build, int size)
{
  NSIContext_t ctx = beginContext();
  const auto start = std::chrono::steady_clock::now();
  build(ctx, size);
  const std::chrono::duration<double> took =
      std::chrono::steady_clock::now() - start;
  NSIEnd(ctx);
  return took.count();
}

void measure(const char *what,
    const std::function<void(NSIContext_t, int)> &build,
    const std::vector<int> &sizes)
{
  std::printf("%s\n%10s %10s %14s %8s\n",
      what,
      "nodes",
      "seconds",
      "us per node",
      "growth");
  double previous = 0;
  for (int size : sizes) {
    const double seconds = secondsToBuild(build, size);
    const double perNode = 1e6 * seconds / size;
    std::printf("%10d %10.3f %14.3f", size, seconds, perNode);
    if (previous > 0)
      std::printf(" %7.2fx", perNode / previous);
    std::printf("\n");
    previous = perNode;
  }
}

} // namespace

int main(int argc, char **argv)
{
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const std::vector<int> depths =
      quick ? std::vector<int>{2500, 5000, 10000}
            : std::vector<int>{6250, 12500, 25000, 50000};
  const std::vector<int> widths =
      quick ? std::vector<int>{50000, 100000}
            : std::vector<int>{125000, 250000, 500000, 1000000};
  measure(
      "transform chain, parents created first",
      [](NSIContext_t ctx, int n) { chain(ctx, n, true); },
      depths);
  measure(
      "transform chain, leaves created first, connected from the leaf",
      [](NSIContext_t ctx, int n) { chain(ctx, n, false); },
      depths);
  measure(
      "the same, then RenderControl start (one ordering pass over the graph)",
      [](NSIContext_t ctx, int n) {
        chain(ctx, n, false);
        start(ctx);
      },
      depths);
  measure("meshes flat under .root", flat, widths);
  measure("the same, then each deleted", flatThenDeleted, widths);
  return 0;
}
