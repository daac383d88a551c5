#pragma once
// Errors between a reference render (the measurement) and a test render (a fit), over the pixels
// both cover (DESIGN.md §13): per-pixel sMAPE (seed 004 Eq. 30) and CIEDE2000 ΔE images, and the
// scalar summaries seed 004 Fig. 17b compares — image RMSE, mean sMAPE, mean ΔE.
#include "brdfkit/render/image.h"

namespace brdfkit::render {

// |a − b| / (|a| + |b|) per channel on linear values, 0 where both are 0 (seed 004 Eq. 30; the
// absolute values keep it in [0, 1] where a fit or a measurement goes negative).
Image smape_image(const Image& reference, const Image& test);
// ΔE00 per pixel (all three channels hold it) after linear sRGB → XYZ (D65) → CIELAB, both images
// relative to the white of luminance `white_y`.
Image delta_e_image(const Image& reference, const Image& test, double white_y);
// The reference white of an HDR render: its 99th-percentile luminance over covered pixels (1 when
// that is 0), so the bright end of the measured sphere sits at L* ≈ 100.
double reference_white(const Image& reference);

struct ImageErrors {
  double rmse = 0;         // sqrt of the mean of (a − b)² over covered pixels and the 3 channels
  double mean_smape = 0;   // mean of the sMAPE image over covered pixels and channels
  double mean_delta_e = 0; // mean ΔE00 over covered pixels
  double white_y = 1;      // the reference white used for ΔE
  size_t pixels = 0;       // pixels compared
};
// InputError when the images differ in size.
ImageErrors compare_images(const Image& reference, const Image& test, double white_y);
// Mean of the covered pixels' channel means (0 when none is covered).
double covered_mean(const Image& image);

}  // namespace brdfkit::render
