#pragma once
// The CIEDE2000 colour difference ΔE00 (CIE 142-2001), as written out step by step by Sharma, Wu &
// Dalal, "The CIEDE2000 Color-Difference Formula: Implementation Notes, Supplementary Test Data,
// and Mathematical Observations", Color Res. Appl. 30(1), 2005.
#include "brdfkit/render/color.h"

namespace brdfkit::render {

// ΔE00 between two CIELAB colours, parametric factors kL = kC = kH = 1 (reference conditions).
// Symmetric in its arguments.
double ciede2000(const Lab& x, const Lab& y);

}  // namespace brdfkit::render
