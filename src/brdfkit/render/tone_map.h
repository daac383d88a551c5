#pragma once
// Display encodings of linear images (DESIGN.md §13): radiance × 2^exposure, clamped to [0, 1],
// through the sRGB transfer function; error images through a monotone-luminance colour map.
#include "brdfkit/render/image.h"
#include "brdfkit/render/image_io.h"

namespace brdfkit::render {

// The exposure (EV) that maps the 99th-percentile luminance of the covered pixels to 0.9, so a
// highlight or two may clip but the body of the object does not; 0 for an image with no light.
double auto_exposure(const Image& image);

// linear × 2^exposure → clamp → sRGB encoding (IEC 61966-2-1) → 8 bits; pixels outside the object
// take `background` (linear, not exposed).
Rgb8Image tone_map(const Image& image, double exposure, const Rgb& background = Rgb(0.18, 0.18, 0.18));

// The mean of the channels of `scalar` on [0, vmax] through Green's cube-helix colour map (Green 2011, Bull. Astr.
// Soc. India 39, 289, Eq. 2: start 0.5, rotations −1.5, hue 1, γ 1), whose luminance rises
// monotonically from black to white; uncovered pixels black.
Rgb8Image false_color(const Image& scalar, double vmax);
// The colour map at fraction t ∈ [0, 1]: display RGB in [0, 1], written to PNG as it is.
Rgb cubehelix(double t);

}  // namespace brdfkit::render
