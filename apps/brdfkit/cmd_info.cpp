// `brdfkit info [FILE...] [--json] [--jobs N] [--data DIR] [--out FILE.json]`: what a measured file
// holds (format, shape, valid share, value ranges, directional albedo). Without FILE: the default
// data (DIR/rgl, DIR/cornell, DIR/merl-slices), or, when DIR has none, a Lambert + GGX material
// that brdfkit tabulates into a temporary MERL file.
#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <unistd.h>

#include <algorithm>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "brdfkit/core/atomic_file.h"
#include "brdfkit/core/error.h"
#include "brdfkit/core/file_digest.h"
#include "brdfkit/core/json_text.h"
#include "brdfkit/measured/load.h"
#include "brdfkit/measured/merl.h"
#include "brdfkit/measured/merl_tabulate.h"
#include "brdfkit/measured/summary.h"
#include "command.h"

namespace brdfkit::cli {
namespace {

namespace fs = std::filesystem;
constexpr double kDeg = kPi / 180;

// The fallback material: Lambert kd/π plus an isotropic GGX lobe ks·D·G/(4 cos θi cos θo) with
// F = 1 and the uncorrelated Smith G = G1(wi)·G1(wo). D = α²/(π cos⁴θ (α² + tan²θ)²) and
// Λ = (√(1 + α² tan²θ) − 1)/2 (DESIGN.md §3–4; Walter et al. 2007 Eq. 33 and 72).
Rgb demo_material(const Vec3d& wi, const Vec3d& wo) {
  const Rgb kd(0.5, 0.3, 0.1);
  const double ks = 0.25, alpha = 0.25, a2 = alpha * alpha;
  const Vec3d h = (wi + wo).normalized();
  auto tan2 = [](double c) { return std::max(0.0, 1 - c * c) / (c * c); };
  const double ch = h.z();
  const double d = a2 / (kPi * ch * ch * ch * ch * (a2 + tan2(ch)) * (a2 + tan2(ch)));
  auto g1 = [&](double c) { return 1 / (1 + (std::sqrt(1 + a2 * tan2(c)) - 1) / 2); };
  return kd * kInvPi + ks * d * g1(wi.z()) * g1(wo.z()) / (4 * wi.z() * wo.z());
}

// Removes the fallback's temporary folder on every way out of the command.
struct TempDir {
  fs::path path;
  ~TempDir() {
    std::error_code ec;
    if (!path.empty()) fs::remove_all(path, ec);
  }
};

struct Source {
  std::vector<fs::path> files;
  std::string description;  // printed: where the data came from
  std::string kind;         // "files", "data", "tabulated"
};

Source default_source(const fs::path& data_dir, TempDir& temp) {
  Source src;
  std::vector<std::string> found;
  for (const char* sub : {"rgl", "cornell", "merl-slices"}) {
    const fs::path dir = data_dir / sub;
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) continue;
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir, ec))
      if (e.is_regular_file(ec) && has_measured_extension(e.path())) files.push_back(e.path());
    std::sort(files.begin(), files.end());  // stable, locale-independent order
    if (files.empty()) continue;
    found.push_back(fmt::format("{} {}", files.size(), sub));
    src.files.insert(src.files.end(), files.begin(), files.end());
  }
  if (!src.files.empty()) {
    src.kind = "data";
    src.description = fmt::format("real measurements in {} ({})", data_dir.string(), fmt::join(found, ", "));
    return src;
  }
  temp.path = fs::temp_directory_path() / fmt::format("brdfkit-info-{}", ::getpid());
  fs::create_directories(temp.path);
  const fs::path file = temp.path / "lambert-ggx.binary";
  merl::write(file, merl::tabulate(demo_material));
  src.kind = "tabulated";
  src.files = {file};
  src.description = fmt::format(
      "{} has no rgl/, cornell/ or merl-slices/ data: a material tabulated by brdfkit (Lambert kd = (0.5, 0.3, "
      "0.1) + GGX alpha = 0.25, ks = 0.25, F = 1) written to {}",
      data_dir.string(), file.string());
  return src;
}

void print_summary(const MeasuredSummary& s) {
  std::cout << fmt::format("{}\n  format {}, {}\n", s.path, s.format, s.dimensions);
  std::cout << fmt::format("  valid: {} of {} ({:.2f} %)\n", s.valid, s.total,
                           s.total ? 100.0 * double(s.valid) / double(s.total) : 0.0);
  std::cout << fmt::format("  {:<8}{:>12}{:>12}{:>12}{:>10}   (valid values, 1/sr)\n", "channel", "min", "max", "mean",
                           "negative");
  const char* names[3] = {"R", "G", "B"};
  for (size_t c = 0; c < 3; ++c)
    std::cout << fmt::format("  {:<8}{:>12.5g}{:>12.5g}{:>12.5g}{:>10}\n", names[c], s.channels[c].min,
                             s.channels[c].max, s.channels[c].mean, s.channels[c].negative);
  if (s.albedo_method == "none") {
    std::cout << "  albedo: not available (the data answer rho(wi, wo) on too small a set to integrate)\n";
    return;
  }
  std::cout << fmt::format("  directional albedo ({}){}:\n",
                           s.albedo_method == "eval"
                               ? "half-vector Gauss-Legendre quadrature of the data; missing = share of the "
                                 "cosine-weighted hemisphere not measured"
                               : "from the file's own samples",
                           s.isotropic ? "" : ", anisotropic data: wi at phi_i = 0");
  std::cout << fmt::format("  {:>8}{:>9}{:>9}{:>9}{:>9}{:>9}\n", "theta_i", "R", "G", "B", "Y", "missing");
  for (const AlbedoRow& r : s.albedo) {
    if (!r.albedo) {
      std::cout << fmt::format("  {:>7.0f}°{:>9}   (not in the data)\n", r.theta_i / kDeg, "-");
      continue;
    }
    const Rgb& a = r.albedo->value;
    std::cout << fmt::format("  {:>7.0f}°{:>9.4f}{:>9.4f}{:>9.4f}{:>9.4f}{:>8.2f}%\n", r.theta_i / kDeg, a[0], a[1],
                             a[2], luminance(a), 100 * r.albedo->missing_fraction);
  }
  if (s.max_albedo)
    std::cout << fmt::format(
        "  max over theta_i in [0°, 80°]: R {:.4f} (at {:.0f}°), G {:.4f} (at {:.0f}°), B {:.4f} (at {:.0f}°); "
        "luminance {:.4f} (at {:.0f}°)\n",
        (*s.max_albedo)[0], s.max_albedo_theta_i[0] / kDeg, (*s.max_albedo)[1], s.max_albedo_theta_i[1] / kDeg,
        (*s.max_albedo)[2], s.max_albedo_theta_i[2] / kDeg, *s.max_luminance, s.max_luminance_theta_i / kDeg);
}

struct Options {
  std::vector<std::string> files;
  bool json = false;
  int jobs = 0;
  std::string data = BRDFKIT_DEFAULT_DATA_DIR;
  std::string out;
};

int run_info(const Options& opt) {
  std::optional<tbb::global_control> limit;
  if (opt.jobs > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, size_t(opt.jobs));

  TempDir temp;
  Source src;
  if (!opt.files.empty()) {
    src.kind = "files";
    src.description = "the files given";
    for (const auto& f : opt.files) src.files.emplace_back(f);
  } else {
    src = default_source(opt.data, temp);
  }
  (opt.json ? std::cerr : std::cout) << "source: " << src.description << "\n";

  // In parallel, results kept in the given order; the first failure in that order is reported.
  std::vector<std::optional<MeasuredSummary>> results(src.files.size());
  std::vector<std::string> digests(src.files.size());
  std::vector<std::exception_ptr> errors(src.files.size());
  tbb::parallel_for(size_t(0), src.files.size(), [&](size_t k) {
    try {
      results[k] = summarize(*load_measured(src.files[k]));
      // SHA-256 names the exact data (DESIGN.md §1); MERL files can be checked against
      // data/merl/merl-sha256.tsv.
      digests[k] = sha256_file(src.files[k]);
    } catch (...) {
      errors[k] = std::current_exception();
    }
  });
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);

  // The fallback's file is removed on return: say so wherever its path is shown.
  if (src.kind == "tabulated") results[0]->path = "(temporary) " + results[0]->path;
  nlohmann::json files = nlohmann::json::array();
  for (size_t k = 0; k < results.size(); ++k) {
    files.push_back(summary_json(*results[k]));
    files.back()["sha256"] = digests[k];
  }
  const nlohmann::json doc = {{"program", "brdfkit"},
                              {"version", BRDFKIT_VERSION},
                              {"command", "info"},
                              {"source", {{"kind", src.kind}, {"description", src.description}}},
                              {"files", files}};
  if (!opt.out.empty()) write_file_atomically(opt.out, json_text(doc) + "\n");
  if (opt.json) {
    std::cout << json_text(doc) << "\n";
  } else {
    for (size_t k = 0; k < results.size(); ++k) {
      if (k) std::cout << "\n";
      print_summary(*results[k]);
    }
  }
  if (!opt.out.empty()) (opt.json ? std::cerr : std::cout) << "results: " << opt.out << "\n";
  return 0;
}

const CommandRegistration reg("info", [](CLI::App& app) {
  auto* sub = app.add_subcommand("info", "Describe measured files: format, valid cells, value ranges, albedo");
  auto opt = std::make_shared<Options>();
  sub->add_option("files", opt->files,
                  "Measured files (MERL .binary, RGL .bsdf, Cornell .brdf, ALTA .alta); none: the default data");
  sub->add_flag("--json", opt->json, "Print JSON instead of tables");
  sub->add_option("--jobs", opt->jobs, "Threads at most; files and albedo angles run in parallel (default: all cores)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--data", opt->data, "Data folder used when no FILE is given (its rgl/, cornell/, merl-slices/)")
      ->capture_default_str();
  sub->add_option("--out", opt->out, "Also write the JSON to this file (atomically)");
  return [opt]() { return run_info(*opt); };
});

}  // namespace
}  // namespace brdfkit::cli
