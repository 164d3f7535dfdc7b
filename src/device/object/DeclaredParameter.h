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

// How a value set compares with its declaration.
enum class ParamVerdict {
  kAccepted,
  kBelowMinimum, // a number (infinities too) below the minimum somewhere
  kAboveMaximum, // above the maximum, nowhere below the minimum
  kRejected,     // not a number, not an accepted value or of the wrong type
};

// What Object::checkedParam() made of a value set.
struct ParamCheck
{
  ParamVerdict verdict{ParamVerdict::kAccepted};
  std::string problem; // "'decay' (7) must be in [0, 4]"
  std::string outcome; // what is used instead: "clamped to 4", "using ..."
};

// Checks `bytes` (of `type`, which must be the definition's valueType for
// its bounds to apply) against the bounds: kAccepted, or the verdict with
// `problem` saying why ("must be in [0, 1]", "must be >= 0", "is not a
// number").
ParamVerdict checkBounds(const introspection::ParameterDefinition &definition,
    ANARIDataType type,
    const void *bytes,
    std::string &problem);

// Moves every component of `bytes` (of the definition's valueType) into
// the definition's bounds, to the nearest one.
void clampToBounds(const introspection::ParameterDefinition &definition,
    ANARIDataType type,
    void *bytes);

// What is wrong with `text` for a STRING parameter whose definition lists
// the accepted values ("must be one of: a, b, c"); empty when it is one of
// them or any text is accepted.
std::string valueProblem(const introspection::ParameterDefinition &definition,
    const std::string &text);

} // namespace prism
