#pragma once
// Reflectance spectra → linear sRGB, brdfkit's convention (DESIGN.md §2): the spectrum is held
// constant outside its range and interpolated linearly to 1 nm; XYZ = Σ S·D65·cmf / Σ D65·ȳ over
// 360–830 nm (CIE 1931 2° observer, D65 linearly interpolated from its 5 nm table), then the
// IEC 61966-2-1 XYZ → linear sRGB matrix. A constant spectrum of 1 maps to (1, 1, 1) within 2e-4.
#include <filesystem>
#include <span>

#include <Eigen/Core>

#include "brdfkit/core/vec.h"

namespace brdfkit {

class SpectrumToRgb {
 public:
  // Loads cie1931-2deg-xyz-1nm.csv and cie-d65-5nm.csv from `cie_dir`; InputError if absent or bad.
  explicit SpectrumToRgb(const std::filesystem::path& cie_dir);

  Eigen::Vector3d xyz(std::span<const double> wavelengths_nm, std::span<const double> values) const;
  Rgb rgb(std::span<const double> wavelengths_nm, std::span<const double> values) const;
  // The linear map spectrum → RGB for one wavelength sampling: rgb = M · values (M is 3 × n).
  // Exact for the convention above (it is linear in S), and what readers apply per sample.
  Eigen::MatrixXd matrix(std::span<const double> wavelengths_nm) const;

 private:
  Eigen::Matrix<double, 471, 3> weights_;  // D65(λ)·cmf(λ) / Σ D65·ȳ at λ = 360…830 nm
};

// XYZ → linear sRGB (IEC 61966-2-1).
Eigen::Matrix3d xyz_to_linear_srgb();

// Where the CIE tables are looked for when no folder is given: $BRDFKIT_CIE_DIR, then
// <data file's folder>/../cie (the shared data layout), then $BRDFKIT_DATA_DIR/cie.
// InputError naming the places tried when none holds them.
std::filesystem::path default_cie_dir(const std::filesystem::path& data_file);

// The process-wide converter for default_cie_dir(data_file) (loaded once per folder).
const SpectrumToRgb& spectrum_to_rgb_for(const std::filesystem::path& data_file);

}  // namespace brdfkit
