// The stability cases, one function each, declared from the table of cases
// (rfStabilityCases.def); they live in rfStabilityCases*.cxx, grouped by their scenes.
#ifndef rfStabilityCases_h
#define rfStabilityCases_h

#include "rfStability.h"

namespace rfstab
{
#define RF_STABILITY_CASE(caseName, function) Row function(const char* name);
#include "rfStabilityCases.def"
#undef RF_STABILITY_CASE
}

#endif
