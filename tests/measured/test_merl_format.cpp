// MERL format: the reference floor rule against hand-computed cells, cell centres, tabulation,
// bit-exact round trips and trilinear look-up (DESIGN.md §2).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

#include "brdfkit/core/error.h"
#include "brdfkit/core/half_diff.h"
#include "brdfkit/measured/merl.h"
#include "brdfkit/measured/merl_brdf.h"
#include "brdfkit/measured/merl_tabulate.h"
#include "support/test_util.h"

using namespace brdfkit;
using merl::Cell;

namespace {

constexpr double kDeg = kPi / 180;

// A table whose red raw value is the cell's offset, so a look-up tells which cell it read.
merl::Table offset_table() {
  merl::Table t;
  for (size_t k = 0; k < merl::kCellCount; ++k) t.set_raw(k, double(k), 1.0, 1.0);
  return t;
}

// A smooth, non-symmetric test BRDF (values far from any scale factor's round numbers).
Rgb wavy(const Vec3d& wi, const Vec3d& wo) {
  const double base = 0.3 + 0.7 * wi.z() * wo.z() + 0.2 * std::sin(3 * wi.x() + 2 * wo.y());  // > 0
  return Rgb(base + 0.01, 2 * base + 0.3, 0.5 * base + 0.123456789);
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

// Direction pairs (θi, φi, θo, φo in degrees) and the cell the reference rule gives, worked out by
// hand from the half/difference angles (h = normalize(wi + wo); θd = angle(wi, h); φd = azimuth of
// wi in the frame (t, b, h) with t = Rz(φh)Ry(θh)x, b = Rz(φh)y; independent of the library):
// iθh = ⌊90·√(θh/90°)⌋, iθd = ⌊θd/90°·90⌋, iφd = ⌊φd/180°·180⌋ after φd < 0 → φd + 180°.
// "mirror": wo = (−wi.x, −wi.y, wi.z) exactly, so h = n (θh = 0) and φd = φi; "n": wi = wo = n.
TEST(MerlLookup, HandComputedCells) {
  struct Case {
    const char* kind;
    double ti, pi, to, po;
    Cell expected;
  };
  const Case cases[] = {
      {"n", 0, 0, 0, 0, {0, 0, 0}},  // all angles 0 exactly
      {"mirror", 35.4, 0, 0, 0, {0, 35, 0}},        // θh 0; θd 35.4° → 35.4; φd 0° → 0
      {"mirror", 62.4, 33.7, 0, 0, {0, 62, 33}},    // θh 0; θd 62.4 → 62.4; φd 33.7 → 33.7
      {"mirror", 88.6, -120.2, 0, 0, {0, 88, 59}},  // θh 0; θd 88.6 (grazing); φd −120.2 + 180 = 59.8
      // θh 19.879°: 90·√(19.879/90) = 42.298; θd 40.438 → 40.438; φd −2.731 (+180) → 177.269
      {"p", 60.3, 4, 20.6, 181, {42, 40, 177}},
      // θh 31.423: 90·√(31.423/90) = 53.179; θd 28.247; φd −117.597 (+180) → 62.403
      {"p", 30, 0, 50.4, 90, {53, 28, 62}},
      // θh 35.486: 56.513; θd 31.462; φd −92.375 (+180) → 87.625
      {"p", 45, 10, 47, 103, {56, 31, 87}},
      // θh 29.760: 51.753; θd 40.243; φd 178.951
      {"p", 10.5, -40, 70, 143, {51, 40, 178}},
      // θh 12.222: 33.165; θd 67.224; φd 79.271
      {"p", 70, 0, 65.5, -170, {33, 67, 79}},
      // θh 7.355: 25.728; θd 12.647; φd 1.732
      {"p", 20, 80, 5.3, -97, {25, 12, 1}},
      // θh 80.440: 90·√(80.44/90) = 85.086; θd 6.430; φd −94.470 (+180) → 85.530  (grazing pair)
      {"p", 80, 0, 81, 13, {85, 6, 85}},
      // θh 71.798: 80.386; θd 86.316 (near 90°); φd −89.842 (+180) → 90.158  (grazing pair)
      {"p", 89, 0, 88.7, 173, {80, 86, 90}},
      // θh 73.292: 81.218; θd 86.868; φd −89.582 (+180) → 90.418
      {"p", 89.5, -90, 88.7, 84, {81, 86, 90}},
      // θh 41.516: 61.127; θd 43.485; φd −0.523 (+180) → 179.477
      {"p", 85, 30, 2, 200, {61, 43, 179}},
      // θh 6.498: 24.183; θd 1.509; φd −173.884 (+180) → 6.116
      {"p", 5, 0, 8, 3, {24, 1, 6}},
      // θh 40.643: 60.481; θd 1.042; φd −128.610 (+180) → 51.390
      {"p", 40, 0, 41.3, 2.5, {60, 1, 51}},
      // θh 22.166: 90·√(22.166/90) = 44.664; θd 52.880; φd −4.088 (+180) → 175.912
      {"p", 75, 120, 30.8, -63, {44, 52, 175}},
      // θh 44.940: 63.597; θd 41.939; φd −158.549 (+180) → 21.451
      {"p", 15, 15, 85, 100, {63, 41, 21}},
      // θh 20.896: 43.367; θd 37.624; φd 40.177
      {"p", 55, -10, 25, -150, {43, 37, 40}},
      // θh 16.988: 39.101; θd 49.815; φd 173.042
      {"p", 33, 200, 66.7, 24, {39, 49, 173}},
      // θh 44.005: 62.932; θd 44.013; φd −2.015 (+180) → 177.985
      {"p", 88, 0, 1.4, 91, {62, 44, 177}},
      // θh 1.908: 90·√(1.908/90) = 13.103; θd 61.484; φd −74.800 (+180) → 105.200
      {"p", 62, 0, 61, 178, {13, 61, 105}},
      // θh 27.427: 49.683; θd 40.309; φd −90.988 (+180) → 89.012
      {"p", 47, -60, 47.8, 63, {49, 40, 89}},
      // θh 0.520: 6.843; θd 12.499; φd 163.949
      {"p", 12, 0, 13, 181.3, {6, 12, 163}},
      // θh 45.000: 63.639; θd 89.646 (near 90°, both directions grazing); φd −89.929 (+180) → 90.071
      {"p", 89.8, 0, 89.7, 179.5, {63, 89, 90}},
  };
  const merl::Table table = offset_table();
  for (const Case& c : cases) {
    const Vec3d wi = spherical_direction(c.ti * kDeg, c.pi * kDeg);
    Vec3d wo;
    if (std::string(c.kind) == "mirror")
      wo = Vec3d(-wi.x(), -wi.y(), wi.z());
    else if (std::string(c.kind) == "n")
      wo = wi;
    else
      wo = spherical_direction(c.to * kDeg, c.po * kDeg);
    const Cell got = merl::cell_of(wi, wo);
    EXPECT_EQ(got.theta_h, c.expected.theta_h) << c.ti << " " << c.pi << " " << c.to << " " << c.po;
    EXPECT_EQ(got.theta_d, c.expected.theta_d) << c.ti << " " << c.pi << " " << c.to << " " << c.po;
    EXPECT_EQ(got.phi_d, c.expected.phi_d) << c.ti << " " << c.pi << " " << c.to << " " << c.po;
    const auto v = table.lookup(wi, wo);
    ASSERT_TRUE(v.has_value());
    EXPECT_EQ((*v)[0], double(merl::cell_offset(c.expected)) * merl::kScale[0]);
  }
}

TEST(MerlLookup, ClampsAndReciprocity) {
  // Beyond the axes: clamped to the last cell; negative θ to the first.
  EXPECT_EQ(merl::cell_of(kPi / 2 + 0.1, kPi / 2 + 0.1, kPi + 0.1), (Cell{89, 89, 179}));
  EXPECT_EQ(merl::cell_of(-0.1, -0.1, 0.0), (Cell{0, 0, 0}));
  // φd = −π → 0 (+π), φd = π exactly → clamped to 179, φd = −0.5° → 179.5 → 179.
  EXPECT_EQ(merl::phi_d_index(-kPi), 0);
  EXPECT_EQ(merl::phi_d_index(kPi), 179);
  EXPECT_EQ(merl::phi_d_index(-0.5 * kDeg), 179);
  // φd and φd − π share a cell (reciprocity): 100.5° and −79.5°.
  EXPECT_EQ(merl::phi_d_index(100.5 * kDeg), merl::phi_d_index(-79.5 * kDeg));
  EXPECT_EQ(merl::phi_d_index(100.5 * kDeg), 100);
  // θh index 45 starts at θh = (45/90)²·90° = 22.5°: 22.4° → 44, 22.6° → 45.
  EXPECT_EQ(merl::theta_h_index(22.4 * kDeg), 44);
  EXPECT_EQ(merl::theta_h_index(22.6 * kDeg), 45);
  // Non-finite angles never index outside the table.
  EXPECT_EQ(merl::theta_h_index(std::nan("")), 0);
  EXPECT_EQ(merl::theta_h_index(HUGE_VAL), 89);
  // Below the horizon: no value.
  const merl::Table t = offset_table();
  EXPECT_FALSE(t.lookup(spherical_direction(0.3, 0.0), Vec3d(0.6, 0, -0.8)).has_value());
}

// Every cell centre (DESIGN.md §2's convention) maps back to its own cell through the floor rule,
// by angles and, for cells above the horizon, through the direction pair.
TEST(MerlLookup, CellCentresRoundTripEveryCell) {
  size_t by_pair = 0;
  for (size_t k = 0; k < merl::kCellCount; ++k) {
    const Cell c = merl::cell_at(k);
    ASSERT_EQ(merl::cell_offset(c), k);
    const HalfDiff hd = merl::cell_centre(c);
    ASSERT_EQ(merl::cell_of(hd.theta_h, hd.theta_d, hd.phi_d), c) << k;
    Vec3d wi, wo;
    if (merl::cell_directions(c, wi, wo)) {
      ASSERT_EQ(merl::cell_of(wi, wo), c) << k;
      ++by_pair;
    }
  }
  std::printf("cells above the horizon checked through direction pairs: %zu of %zu\n", by_pair, merl::kCellCount);
  EXPECT_GT(by_pair, merl::kCellCount / 2);
}

// Tabulation fills each cell at its centre; the look-up at that centre returns the stored value
// exactly, and that value is ρ within the rounding of ρ/scale·scale.
TEST(MerlTabulate, LookupAtCentresReturnsTabulatedValues) {
  const merl::Table t = merl::tabulate(wavy);
  size_t valid = 0, below = 0;
  for (size_t k = 0; k < merl::kCellCount; ++k) {
    const Cell c = merl::cell_at(k);
    Vec3d wi, wo;
    if (!merl::cell_directions(c, wi, wo)) {
      // Below the horizon: raw −1 (not measured), as in real MERL files.
      ASSERT_FALSE(t.valid(k));
      ASSERT_EQ(t.raw(0, k), -1.0);
      ASSERT_EQ(t.raw(2, k), -1.0);
      const HalfDiff hd = merl::cell_centre(c);
      ASSERT_FALSE(t.lookup(hd.theta_h, hd.theta_d, hd.phi_d).has_value());
      ++below;
      continue;
    }
    ++valid;
    ASSERT_TRUE(t.valid(k));
    const auto v = t.lookup(wi, wo);
    ASSERT_TRUE(v.has_value()) << k;
    ASSERT_EQ((*v)[0], t.value(k)[0]);
    ASSERT_EQ((*v)[1], t.value(k)[1]);
    ASSERT_EQ((*v)[2], t.value(k)[2]);
    const Rgb expect = wavy(wi, wo);
    for (int ch = 0; ch < 3; ++ch) ASSERT_NEAR((*v)[ch], expect[ch], 4e-16 * std::abs(expect[ch])) << k;
    // By angles as well.
    const HalfDiff hd = merl::cell_centre(c);
    ASSERT_EQ(t.lookup(hd.theta_h, hd.theta_d, hd.phi_d)->matrix(), v->matrix());
  }
  std::printf("tabulated: %zu valid cells, %zu below the horizon (raw -1)\n", valid, below);
  EXPECT_EQ(valid, t.valid_count());
  EXPECT_EQ(valid + below, merl::kCellCount);
  // The count of real full-size MERL-format files (DESIGN.md §12: 1 096 216 valid cells).
  EXPECT_EQ(valid, 1096216u);
}

TEST(MerlTabulate, DeterministicAndRejectsNonFinite) {
  const merl::Table a = merl::tabulate(wavy), b = merl::tabulate(wavy);
  EXPECT_EQ(std::memcmp(a.raw_data(), b.raw_data(), 3 * merl::kCellCount * sizeof(double)), 0);
  EXPECT_THROW(merl::tabulate([](const Vec3d& wi, const Vec3d&) -> Rgb {
                 return Rgb(wi.z() > 0.5 ? std::nan("") : 1.0, 1.0, 1.0);
               }),
               InputError);
}

// tabulate → write → read gives the same raw doubles and mask; writing the read table again gives
// the same bytes; the file has MERL's exact size and header.
TEST(MerlFile, RoundTripIsBitIdentical) {
  const auto dir = test::scratch_dir("merl_roundtrip");
  const merl::Table t = merl::tabulate(wavy);
  merl::write(dir / "a.binary", t);
  EXPECT_EQ(std::filesystem::file_size(dir / "a.binary"), merl::kFileBytes);
  const merl::Table r = merl::read(dir / "a.binary");
  EXPECT_EQ(std::memcmp(t.raw_data(), r.raw_data(), 3 * merl::kCellCount * sizeof(double)), 0);
  for (size_t k = 0; k < merl::kCellCount; ++k) ASSERT_EQ(t.valid(k), r.valid(k));
  // Both kinds of cell are in the file, so the mask read computes is compared on both.
  EXPECT_GT(r.valid_count(), 0u);
  EXPECT_LT(r.valid_count(), merl::kCellCount);
  merl::write(dir / "b.binary", r);
  const std::string a = slurp(dir / "a.binary"), b = slurp(dir / "b.binary");
  EXPECT_TRUE(a == b);
  std::int32_t dims[3];
  std::memcpy(dims, a.data(), sizeof dims);
  EXPECT_EQ(dims[0], 90);
  EXPECT_EQ(dims[1], 90);
  EXPECT_EQ(dims[2], 180);
  // Channel blocks R, G, B: the G value of cell k sits at 12 + 8·(1458000 + k).
  const size_t k = merl::cell_offset({30, 40, 50});
  double g;
  std::memcpy(&g, a.data() + 12 + 8 * (merl::kCellCount + k), sizeof g);
  EXPECT_EQ(g, t.raw(1, k));
  // No temporary left next to the output.
  size_t files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 2u);
  std::filesystem::remove_all(dir);
}

// A file written byte by byte (header 90 90 180, then the R, G and B blocks of doubles) reads
// with the reference reader's channel scales, written here as MERL's BRDFRead.cpp defines them:
// RED_SCALE 1.0/1500, GREEN_SCALE 1.15/1500, BLUE_SCALE 1.66/1500.
TEST(MerlFile, HandWrittenFileReadsWithTheReferenceChannelScales) {
  const auto dir = test::scratch_dir("merl_scales");
  std::string bytes(merl::kFileBytes, '\0');
  const std::int32_t dims[3] = {90, 90, 180};
  std::memcpy(bytes.data(), dims, sizeof dims);
  const double raw[3] = {1500.0, 3000.0, 750.0};
  for (int c = 0; c < 3; ++c)
    for (size_t k = 0; k < merl::kCellCount; ++k)
      std::memcpy(bytes.data() + 12 + 8 * (size_t(c) * merl::kCellCount + k), &raw[c], sizeof(double));
  std::ofstream(dir / "hand.binary", std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
  const merl::Table t = merl::read(dir / "hand.binary");
  const auto v = t.lookup(20 * kDeg, 30 * kDeg, 40 * kDeg);
  ASSERT_TRUE(v.has_value());
  EXPECT_DOUBLE_EQ((*v)[0], 1.0);
  EXPECT_DOUBLE_EQ((*v)[1], 2.0 * 1.15);
  EXPECT_DOUBLE_EQ((*v)[2], 0.5 * 1.66);
  std::filesystem::remove_all(dir);
}

// Raw stored value of each cell = 1 + 2 iθh + 3 iθd + 0.5 iφd (affine in the index): trilinear
// look-up reproduces the affine function at any point between centres, and the φd axis wraps.
TEST(MerlLookup, TrilinearIsExactForAffineTables) {
  merl::Table t;
  for (size_t k = 0; k < merl::kCellCount; ++k) {
    const Cell c = merl::cell_at(k);
    const double v = 1 + 2.0 * c.theta_h + 3.0 * c.theta_d + 0.5 * c.phi_d;
    t.set_raw(k, v, v, v);
  }
  auto angles_of = [](double xh, double xd, double xp) {
    // inverse of merl::index_coordinates
    const double u = (xh + 0.5) / 90;
    return Vec3d(u * u * kPi / 2, (xd + 0.5) / 90 * kPi / 2, (xp + 0.5) / 180 * kPi);
  };
  const double pts[][3] = {{10.25, 20.5, 30.75}, {0.1, 88.9, 1.0}, {45.0, 45.0, 90.0}, {88.3, 0.7, 177.2}};
  for (const auto& p : pts) {
    const Vec3d a = angles_of(p[0], p[1], p[2]);
    const auto v = t.lookup_trilinear(a[0], a[1], a[2]);
    ASSERT_TRUE(v.has_value());
    EXPECT_NEAR((*v)[0] / merl::kScale[0], 1 + 2 * p[0] + 3 * p[1] + 0.5 * p[2], 1e-9);
  }
  // Between φd cells 179 and 0 (φd = π − tiny, i.e. index 179.5): halfway between them.
  const Vec3d a = angles_of(20, 30, 179.5);
  EXPECT_NEAR((*t.lookup_trilinear(a[0], a[1], a[2]))[0] / merl::kScale[0], 1 + 40 + 90 + 0.5 * (179 * 0.5 + 0), 1e-9);
  // At a centre: the cell's own value.
  const Vec3d c = angles_of(12, 34, 56);
  EXPECT_NEAR((*t.lookup_trilinear(c[0], c[1], c[2]))[0] / merl::kScale[0], 1 + 24 + 102 + 28, 1e-9);
  // Invalid corners are left out: make the θh = 13 and 14 layers invalid; at 12.5 → layer 12 only,
  // at 13.3 every corner is invalid.
  for (int h : {13, 14})
    for (int d = 0; d < 90; ++d)
      for (int p = 0; p < 180; ++p) t.set_raw(merl::cell_offset({h, d, p}), -1, -1, -1);
  const Vec3d m = angles_of(12.5, 34, 56);
  EXPECT_NEAR((*t.lookup_trilinear(m[0], m[1], m[2]))[0] / merl::kScale[0], 1 + 24 + 102 + 28, 1e-9);
  const Vec3d only_invalid = angles_of(13.3, 34, 56);
  EXPECT_FALSE(t.lookup_trilinear(only_invalid[0], only_invalid[1], only_invalid[2]).has_value());
  EXPECT_FALSE(t.lookup(only_invalid[0], only_invalid[1], only_invalid[2]).has_value());
}

// Cell weights are the exact measure of each cell in the space of direction pairs: all cells
// together 8π² (θh, θd ∈ [0, π/2], φh, φd ∈ [0, 2π), Jacobian 4 cos θd), the cells above the
// horizon ≈ (2π)², and Σ w ρ cosθi cosθo for ρ = 1/π ≈ π (∫∫ cosθi cosθo/π dωi dωo = π·π/π).
TEST(MerlBrdf, SampleWeightsIntegrateThePairDomain) {
  double all = 0;
  for (size_t k = 0; k < merl::kCellCount; ++k) all += merl_cell_weight(merl::cell_at(k));
  EXPECT_NEAR(all, 8 * kPi * kPi, 1e-9);
  const MerlBrdf brdf(merl::tabulate([](const Vec3d&, const Vec3d&) -> Rgb { return Rgb::Constant(kInvPi); }), "lambert");
  const SampleSet s = brdf.samples();
  EXPECT_EQ(s.size(), brdf.table().valid_count());
  double sum_w = 0, sum_cos = 0;
  for (size_t k = 0; k < s.size(); ++k) {
    ASSERT_TRUE(s.valid[k]);
    ASSERT_GT(s.wi_z[k], 0);
    ASSERT_GT(s.wo_z[k], 0);
    ASSERT_NEAR(s.rgb[0][k], kInvPi, 1e-15);
    sum_w += s.weight[k];
    sum_cos += s.weight[k] * s.rgb[0][k] * s.wi_z[k] * s.wo_z[k];
  }
  std::printf("sum of weights %.5f (4 pi^2 = %.5f), sum w cos cos / pi %.5f (pi = %.5f)\n", sum_w, 4 * kPi * kPi,
              sum_cos, kPi);
  EXPECT_NEAR(sum_w / (4 * kPi * kPi), 1.0, 0.02);
  EXPECT_NEAR(sum_cos / kPi, 1.0, 0.01);
  // Invalid cells give no sample.
  merl::Table t = brdf.table();
  t.set_raw(merl::cell_offset({10, 10, 10}), -1, 0.5, 0.5);
  EXPECT_EQ(MerlBrdf(t, "x").samples().size(), s.size() - 1);
}
