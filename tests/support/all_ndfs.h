#pragma once
// Every distribution of ndf/, for the tests.
#include "brdfkit/ndf/abc_facet.h"
#include "brdfkit/ndf/beckmann.h"
#include "brdfkit/ndf/blinn_phong.h"
#include "brdfkit/ndf/exponential.h"
#include "brdfkit/ndf/exponential_power.h"
#include "brdfkit/ndf/gaussian.h"
#include "brdfkit/ndf/ggx.h"
#include "brdfkit/ndf/gtr.h"
#include "brdfkit/ndf/sawicki_rational.h"
#include "brdfkit/ndf/schlick_rational.h"
#include "brdfkit/ndf/sgd.h"
#include "brdfkit/ndf/tabulated.h"
