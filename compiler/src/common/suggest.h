#pragma once
// closestMatch is public (the command line suggests option names with it too).
#include "hexc/suggest.h"
