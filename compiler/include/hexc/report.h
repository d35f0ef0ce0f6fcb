#pragma once
// Diagnostics in the order hexc reports them, for a caller that prints or hands them on as the command line does.
#include "hexc/diagnostics.h"

namespace hexc {

// `diags` as a run prints them: each file's together, in the order files first appear, by line and column.
Diagnostics byPosition(Diagnostics diags);

}  // namespace hexc
