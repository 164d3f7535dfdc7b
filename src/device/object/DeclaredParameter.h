// A parameter value checked against its declaration in the introspection
// tables (the API definitions): its bounds and its accepted values. The
// definitions are the one place defaults, bounds and accepted values are
// written; Object::param() reads through these checks.
#pragma once

#include "anari/anari.h"

#include "../introspection/Introspection.h"

#include <string>

namespace prism {

// `bytes` (C bytes of `type`) as a message shows them: "0.5", "(1, 0, 0)".
std::string valueText(ANARIDataType type, const void *bytes);

// What is wrong with `bytes` (of `type`, which must be the definition's
// valueType for its bounds to apply): "must be in [0, 1]", "must be >= 0",
// "is not a number"; empty when nothing is.
std::string boundsProblem(const introspection::ParameterDefinition &definition,
    ANARIDataType type,
    const void *bytes);

// What is wrong with `text` for a STRING parameter whose definition lists
// the accepted values ("must be one of: a, b, c"); empty when it is one of
// them or any text is accepted.
std::string valueProblem(const introspection::ParameterDefinition &definition,
    const std::string &text);

} // namespace prism
