// Issue #5's surrogate acceptance, on all materials (too slow for the CI test budget; the
// always-run part is tests/surrogates/): for each of ≥ 10 published Bagher SGD fits
// (bagher2012-sgd.json) tabulated as a full-size MERL table,
//   1. brdfkit's fit of Löw's smooth model (low-smooth) under `low-e2` must reach an E2 ≤ the
//      E2 of Löw's published smooth parameters (low2012-smooth-E2.json) on that surrogate;
//   2. the `bagher` procedure must recover the surrogate's own parameters.
// A plain program (no Google Benchmark timing): prints the table (per material: both E2 values,
// the fit's wall and CPU seconds, the bagher recovery errors and CPU seconds, the tabulation's CPU
// seconds), the two shapes, and exits 1 if a row fails.
//   surrogate_acceptance [--starts N] [--coarsen K] [--bagher-starts N] [material …]
// One start is the default: start 0 is already the best point of a shape scan (fit/start_scan.h)
// with colours from the linearized solve; on alum-bronze 3 more random starts found the same E2
// (0.0138318) for 145.5 s CPU instead of 9.3 s.
#include <fmt/format.h>

#include <array>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "brdfkit/core/error.h"
#include "brdfkit/fit/procedure/procedure.h"
#include "brdfkit/measured/merl_brdf.h"
#include "brdfkit/measured/merl_tabulate.h"
#include "brdfkit/models/published_fits.h"

using namespace brdfkit;

namespace {

// Sharp metals, paints, plastics, fabrics, a wood and a stone: the spread of the MERL set.
const std::vector<std::string> kDefaultMaterials = {
    "alum-bronze", "blue-acrylic",  "chrome",          "gold-metallic-paint", "green-plastic", "hematite",
    "nickel",      "pearl-paint",   "red-fabric",      "specular-black-phenolic", "white-paint", "cherry-235"};

double param(const Model& m, const ParamValues& v, const char* name, int c) {
  return v.values[size_t(c)][size_t(find_param(m.params(), name))];
}

// Process CPU seconds (user + sys, all threads): the machine is shared, so wall time alone says
// little.
double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// The surrogate's MERL table, one channel per pass: the same values as tabulating Brdf::eval, but
// the SGD normalization's Γ(s, x) cache (ndf/upper_gamma.h, one entry per thread) then sees one
// channel's (s, x) at a time instead of alternating R, G, B (a cache miss per channel per cell:
// ~3/4 of the runner's time before).
merl::Table tabulate_by_channel(const Brdf& brdf) {
  auto raw = std::make_unique<double[]>(3 * merl::kCellCount);
  for (int c = 0; c < 3; ++c) {
    const merl::Table t = merl::tabulate([&](const Vec3d& wi, const Vec3d& wo) {
      return Rgb::Constant(brdf.model().eval(brdf.values().channel(c), c, wi, wo));
    });
    std::copy_n(t.raw_data() + size_t(c) * merl::kCellCount, merl::kCellCount, raw.get() + size_t(c) * merl::kCellCount);
  }
  return merl::Table(std::move(raw));
}

}  // namespace

int main(int argc, char** argv) {
  int starts = 1, coarsen = 1, bagher_starts = 8;
  std::vector<std::string> materials;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--starts" && i + 1 < argc) starts = std::atoi(argv[++i]);
    else if (a == "--coarsen" && i + 1 < argc) coarsen = std::atoi(argv[++i]);
    else if (a == "--bagher-starts" && i + 1 < argc) bagher_starts = std::atoi(argv[++i]);
    else materials.push_back(a);
  }
  if (materials.empty()) materials = kDefaultMaterials;
  const std::filesystem::path dir = std::filesystem::path(BRDFKIT_BENCH_DATA_DIR) / "published-fits";
  try {
    const PublishedFits sgd = PublishedFits::read(dir / "bagher2012-sgd.json");
    const PublishedFits smooth = PublishedFits::read(dir / "low2012-smooth-E2.json");
    const Model& low = model_by_name("low-smooth");
    fmt::print("low-e2 fits: {} start(s), grid coarsened by {}\n", starts, coarsen);
    fmt::print("{:<24} {:>12} {:>12} {:>6} {:>7} {:>7} | {:>8} {:>8} {:>8} {:>8} {:>8} {:>8} {:>7} {:>6} | {:>6}\n",
               "material", "E2 published", "E2 brdfkit", "ok", "fit s", "fit cpu", "kd", "ks", "alpha", "p", "F0", "F1",
               "ok", "cpu", "tab cpu");
    int failures = 0;
    double total_cpu = 0;
    std::vector<std::string> details;
    for (const std::string& material : materials) {
      const double c0 = cpu_seconds();
      const Brdf truth = sgd.brdf(material);
      const MerlBrdf data(tabulate_by_channel(truth), material + " (SGD surrogate)");
      const double c1 = cpu_seconds();
      // 1. Löw's smooth model under E2 (seed 003 Eq. 32–33).
      const Brdf published = smooth.brdf(material);
      const fit::Metric e2 = fit::make_metric("low-e2", data, {coarsen});
      const double e2_published = e2.value(published.model(), published.values());
      fit::FitSettings opt;
      opt.procedure = "low-e2";
      opt.starts = starts;
      opt.coarsen = coarsen;
      const auto t0 = std::chrono::steady_clock::now();
      const fit::ProcedureResult lr = fit::run_procedure(low, data, opt);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const double c2 = cpu_seconds();
      const bool e2_ok = lr.fit.metric_value <= e2_published;
      // 2. The bagher procedure recovers the surrogate's parameters (max relative error over
      // channels; F0 and F1 relative to max(|F0|, |F1|): they enter F = F0 + (1 − F0)(1 − cosθd)⁵ −
      // F1 cosθd together, and a published F0 may be ~0, e.g. chrome's blue 3.2e-13 next to F1 = −1,
      // where 1e-16 of round-off is a relative error of 4e-4).
      fit::FitSettings bopt;
      bopt.procedure = "bagher";
      bopt.coarsen = 8;  // the reported bagher metric only
      // From one start the θd = 0 slice fit of cherry-235's red channel (p 0.036) ended at
      // p ≈ 1.9, α ≈ 0.16, and white-paint's wide blue lobe (α 0.54) was off by 24 %.
      bopt.starts = bagher_starts;
      const fit::ProcedureResult br = fit::run_procedure(truth.model(), data, bopt);
      std::array<double, 6> err{};
      const char* names[] = {"kd", "ks", "alpha", "p", "F0", "F1"};
      for (size_t k = 0; k < 6; ++k)
        for (int c = 0; c < 3; ++c) {
          const double x = param(truth.model(), truth.values(), names[k], c);
          const double y = param(truth.model(), br.fit.values, names[k], c);
          const double ref =
              k >= 4 ? std::max(std::abs(param(truth.model(), truth.values(), "F0", c)),
                                std::abs(param(truth.model(), truth.values(), "F1", c)))
                     : std::abs(x);
          err[k] = std::max(err[k], std::abs(y - x) / ref);
        }
      bool rec_ok = true;
      for (double e : err) rec_ok = rec_ok && e < 1e-4;
      failures += !e2_ok + !rec_ok;
      const double c3 = cpu_seconds();
      total_cpu += c3 - c0;
      fmt::print(
          "{:<24} {:>12.6g} {:>12.6g} {:>6} {:>7.1f} {:>7.1f} | {:>8.1e} {:>8.1e} {:>8.1e} {:>8.1e} {:>8.1e} {:>8.1e} {:>7} "
          "{:>6.1f} | {:>6.1f}\n",
          material, e2_published, lr.fit.metric_value, e2_ok ? "yes" : "NO", seconds, c2 - c1, err[0], err[1], err[2],
          err[3], err[4], err[5], rec_ok ? "yes" : "NO", c3 - c2, c1 - c0);
      std::fflush(stdout);
      // The shapes behind the two E2 values (colours are per channel; the shape is shared).
      auto shape = [&](const Brdf& b) {
        return fmt::format("B {:.5g} C {:.5g} eta {:.5g} kd {:.3g}/{:.3g}/{:.3g} A {:.4g}/{:.4g}/{:.4g}",
                           param(b.model(), b.values(), "B", 0), param(b.model(), b.values(), "C", 0),
                           param(b.model(), b.values(), "eta", 0), param(b.model(), b.values(), "kd", 0),
                           param(b.model(), b.values(), "kd", 1), param(b.model(), b.values(), "kd", 2),
                           param(b.model(), b.values(), "A", 0), param(b.model(), b.values(), "A", 1),
                           param(b.model(), b.values(), "A", 2));
      };
      details.push_back(fmt::format("{}: published {}\n{:>{}}  brdfkit   {} (best start {}, {} iterations)", material,
                                    shape(published), "", material.size(), shape(Brdf(low, lr.fit.values)),
                                    lr.fit.best_start, lr.fit.iterations));
    }
    for (const std::string& d : details) fmt::print("{}\n", d);
    fmt::print("{} failure(s); {:.1f} s CPU in all (user + sys)\n", failures, total_cpu);
    return failures == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "surrogate_acceptance: {}\n", e.what());
    return 2;
  }
}
