// Every subtype the prism device creates, added to a registry: the one
// place above all categories that knows them all.
#pragma once

#include "object/SubtypeRegistry.h"

namespace prism {

void addPrismSubtypes(SubtypeRegistry &registry);

} // namespace prism
