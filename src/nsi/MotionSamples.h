// Attributes set at several times (NSISetAttributeAtTime) read at the times
// a render samples the shutter: linear between the samples around a time,
// held before the first and after the last.
#pragma once

#include "Graph.h"

#include <map>
#include <vector>

namespace prism::nsi {

// Number samples by time, each of the same length.
using NumberSamples = std::map<double, std::vector<double>>;

// An attribute moves when it has no plain value and two or more samples.
bool isMoving(const Attribute &attribute);

// The samples of a moving attribute as numbers; false when they differ in
// length (then `samples` holds them all anyway).
bool numberSamples(const Attribute &attribute, NumberSamples &samples);

// The samples at `time`, linear between its neighbours, held outside.
std::vector<double> numbersAt(const NumberSamples &samples, double time);

} // namespace prism::nsi
