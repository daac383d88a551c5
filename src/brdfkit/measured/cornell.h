#pragma once
// Cornell Light Measurement Laboratory scattered spectral BRDF samples (pbrt-v2 `scenes/brdfs/`).
// Format (DESIGN.md §2, data/README.md): `#` comment lines, CRLF; the wavelength count and the
// wavelengths (nm); then one sample per line: θi φi θs φs (radians) and one value per wavelength
// (sr⁻¹). Spectra become linear sRGB through spectral_rgb.h (brdfkit's convention).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "brdfkit/measured/measured_brdf.h"

namespace brdfkit {

class CornellBrdf final : public MeasuredBrdf {
 public:
  // `cie_dir`: folder of the CIE tables; empty = default_spectrum_to_rgb() (spectral_rgb.h: the
  // compiled-in tables unless $BRDFKIT_CIE_DIR names a folder).
  explicit CornellBrdf(const std::filesystem::path& file, const std::filesystem::path& cie_dir = {});

  std::string format() const override { return "cornell"; }
  std::string path() const override { return path_; }
  std::string dimensions() const override;
  // Scattered data answer no arbitrary (wi, wo): always nullopt.
  std::optional<Rgb> eval(const Vec3d&, const Vec3d&) const override { return std::nullopt; }
  // One sample per line, wi = (θi, φi), wo = (θs, φs), raw linear-sRGB values (may be < 0: out of
  // gamut). weight = solid angle of wo the sample stands for: the files sample 10 rings
  // 1 − cos θs = (k/10)², k = 0…9, on the half plane φs ∈ [−180°, 0°]. A sample of ring k gets
  // 2π·(b_{k+1} − b_k) / (number of samples of ring k at that θi), with band edges
  // b_k = ((k − ½)/10)² in 1 − cos θs (b_0 = 0, b_10 = 1: the last band ends at the horizon). The
  // weights of one θi thus sum to 2π (less the band of a ring absent at that θi): the half plane
  // stands for the whole hemisphere by isotropy (ρ(φ) = ρ(−φ)), and a ring's missing retro-
  // reflection neighbourhood is spread over its measured samples.
  SampleSet samples() const override;
  std::vector<std::pair<double, Rgb>> albedos_from_samples() const override;

  // a(θi) = Σ ρ cosθs · weight over the samples of that θi (θi as in the file, radians).
  Rgb directional_albedo_from_samples(double theta_i) const;
  std::vector<double> theta_i_values() const;  // distinct θi of the file, ascending
  const std::vector<double>& wavelengths() const { return wavelengths_; }
  // Raw spectral values of sample k (one per wavelength).
  const std::vector<double>& spectrum(size_t k) const { return spectra_[k]; }

 private:
  std::string path_;
  std::vector<double> wavelengths_;
  std::vector<std::vector<double>> spectra_;
  SampleSet samples_;
};

std::unique_ptr<MeasuredBrdf> read_cornell(const std::filesystem::path& file);

}  // namespace brdfkit
