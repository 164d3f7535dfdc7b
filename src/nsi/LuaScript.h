// NSIEvaluate type "lua": runs `script` and then `filename` in one sandboxed
// Lua 5.4 state whose `nsi` table calls back into the context `ctx` through
// the C API. Errors (with the chunk's name and line) go to `report`.
#pragma once

#include "GeometryBuilder.h"
#include "ParameterList.h"

namespace prism::nsi {

// False when libnsi was built without Lua.
bool luaAvailable();

// `fileName` is the already expanded `filename` (empty when none).
void runLua(NSIContext_t ctx,
    const ReportFunction &report,
    const ParameterList &params,
    const std::string &fileName);

} // namespace prism::nsi
