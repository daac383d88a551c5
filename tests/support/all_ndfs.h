#pragma once
// Every distribution of ndf/, for the tests: the list of ndf/distributions.h and the two that are
// not in it (the unnormalized ABC facet and the tabulated distribution).
#include "brdfkit/ndf/abc_facet.h"
#include "brdfkit/ndf/distributions.h"
#include "brdfkit/ndf/tabulated.h"
