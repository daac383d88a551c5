#pragma once
// The CIE tables of spectral → RGB conversion (spectral_rgb.h), compiled into brdfkit from the
// repository's resources/cie/ (CMakeLists.txt embeds them): standard constants, so a spectral file
// converts the same wherever it lies, with no data folder beside it.
#include <string_view>
#include <utility>
#include <vector>

namespace brdfkit::cie {

// (file name, contents) pairs: cie1931-2deg-xyz-1nm.csv and cie-d65-5nm.csv, as in resources/cie/.
const std::vector<std::pair<std::string_view, std::string_view>>& embedded_tables();

}  // namespace brdfkit::cie
