#pragma once
// Reflectance spectra → linear sRGB, brdfkit's convention (DESIGN.md §2): the spectrum is held
// constant outside its range and interpolated linearly to 1 nm; XYZ = Σ S·D65·cmf / Σ D65·ȳ over
// 360–830 nm (CIE 1931 2° observer, D65 linearly interpolated from its 5 nm table), then the
// IEC 61966-2-1 XYZ → linear sRGB matrix. A constant spectrum of 1 maps to (1, 1, 1) within 2e-4.
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "brdfkit/core/vec.h"

namespace brdfkit {

class SpectrumToRgb {
 public:
  // The CIE tables compiled into brdfkit (the repository's resources/cie/, cie_tables.h).
  SpectrumToRgb();
  // Loads cie1931-2deg-xyz-1nm.csv and cie-d65-5nm.csv from `cie_dir`; InputError if absent or bad.
  explicit SpectrumToRgb(const std::filesystem::path& cie_dir);

  Eigen::Vector3d xyz(std::span<const double> wavelengths_nm, std::span<const double> values) const;
  Rgb rgb(std::span<const double> wavelengths_nm, std::span<const double> values) const;
  // The linear map spectrum → RGB for one wavelength sampling: rgb = M · values (M is 3 × n).
  // Exact for the convention above (it is linear in S), and what readers apply per sample.
  Eigen::MatrixXd matrix(std::span<const double> wavelengths_nm) const;

 private:
  // Rows of the two tables (first column λ in nm); `where` names their source in errors.
  void set_weights(const std::vector<std::vector<double>>& cmf, const std::vector<std::vector<double>>& d65,
                   const std::string& where);

  Eigen::Matrix<double, 471, 3> weights_;  // D65(λ)·cmf(λ) / Σ D65·ȳ at λ = 360…830 nm
};

// XYZ → linear sRGB (IEC 61966-2-1).
Eigen::Matrix3d xyz_to_linear_srgb();

// The process-wide converter of the compiled-in tables.
const SpectrumToRgb& built_in_spectrum_to_rgb();

// The converter spectral readers use when given no folder: the tables of the folder named by
// $BRDFKIT_CIE_DIR when it is set (InputError naming it when the folder lacks them; loaded once
// per folder), the compiled-in ones otherwise. Never a folder found near the data: a file must
// convert the same wherever it lies.
const SpectrumToRgb& default_spectrum_to_rgb();

}  // namespace brdfkit
