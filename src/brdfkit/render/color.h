#pragma once
// Colour conversions for images: linear sRGB (Rec. 709 primaries, D65) ↔ CIE XYZ, XYZ → CIELAB
// and the sRGB transfer function.
#include "brdfkit/core/vec.h"

namespace brdfkit::render {

struct Lab {
  double L = 0, a = 0, b = 0;
};

// IEC 61966-2-1:1999 §5.2: XYZ (Y of white = 1) from linear sRGB.
Vec3d linear_srgb_to_xyz(const Rgb& rgb);
// D65 white of IEC 61966-2-1 (x = 0.3127, y = 0.3290) with Y = 1.
Vec3d d65_white();
// CIE 15:2004 §8.2.1: CIELAB of XYZ relative to the white `white` (same Y scale).
Lab xyz_to_lab(const Vec3d& xyz, const Vec3d& white);
// Linear sRGB → CIELAB under D65 with reference white luminance `white_y` (HDR images: the caller
// states which white it uses, DESIGN.md §13).
Lab linear_srgb_to_lab(const Rgb& rgb, double white_y);
// IEC 61966-2-1:1999 §5.2 encoding (linear [0, 1] → non-linear [0, 1]).
double srgb_encode(double linear);

}  // namespace brdfkit::render
