#pragma once
// Each setting's names in its enum's order, as a material spells them: one table per enum, read by the parser
// (the index of the name is the value) and written by toString (hexc/material.h).
#include <string>
#include <vector>

#include "hexc/material.h"

namespace hexc {

extern const std::vector<std::string> kKinds, kChannels, kColorSpaces, kModes, kMasks, kProjections, kBlends, kLods, kLayerBlends,
    kLayerWeights;

// A slot's engine roles (its `role`, docs/engines.md#slots-and-engine-inputs), and the kind of slot each takes.
extern const std::vector<std::string> kRoles;
SlotKind roleKind(const std::string& role);

// The kinds that have a property, as a message lists them: "`color` or `scalar`".
std::string kindsWhere(bool SlotKindRow::*property);

}  // namespace hexc
