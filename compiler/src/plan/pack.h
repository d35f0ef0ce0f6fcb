#pragma once
// Channel packing (docs/material-format.md#pack): which read slots share one texture hexc writes.
#include "plan/plan.h"

namespace hexc {

// plan.packs, and each packed slot's pack and channel. Slots pack when they share a lattice, the taps and a texture
// size and their channels fit four: a colour slot's RGB (its texture opaque) with a linear scalar's channel in alpha,
// or up to four linear scalars. Grouped in declaration order, so the result is the same on every run. A slot left out
// of a pack its lattice has gets warning HX124 with the reason.
void planPacks(ShaderPlan& plan);

}  // namespace hexc
