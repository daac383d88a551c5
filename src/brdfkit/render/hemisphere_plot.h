#pragma once
// A function over the hemisphere (a microfacet distribution D(h)) drawn flat, as seed 002's
// Figs. 11–13 draw the distributions it estimates: the parabolic map (Heidrich & Seidel 1998,
// "View-independent environment maps": the direction (x, y, z), z ≥ 0, at the disk point
// (x, y)/(1 + z)), +x to the right, +y up, the normal at the centre, the horizon on the rim.
#include <functional>

#include "brdfkit/core/vec.h"
#include "brdfkit/render/image.h"
#include "brdfkit/render/image_io.h"

namespace brdfkit::render {

// The direction at disk point (u, v), u² + v² ≤ 1 (the map's inverse).
Vec3d parabolic_direction(double u, double v);

// f at every pixel centre inside the unit disk of a size × size image (all three channels), those
// pixels covered, the rest not.
Image parabolic_map(const std::function<double(const Vec3d&)>& f, int size);

// log10(f / max f) over `decades` decades through the cube-helix map (tone_map.h): the maximum
// white, 10^−decades of it and less black, outside the disk black.
Rgb8Image log_false_color(const Image& values, double decades);

}  // namespace brdfkit::render
