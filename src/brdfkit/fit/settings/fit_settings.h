#pragma once
// The settings of one fit: the one type the command line, `fit-all`, the procedures, the solver
// and the Python module read (each field's name is its setting's name in errors and in Python;
// the command line shows it as a flag, `max_iterations` as `--max-iterations`). validate() names
// the first bad setting and what it accepts (SettingError).
#include <cstdint>
#include <map>
#include <string>
#include <utility>

namespace brdfkit::fit {

// Search boxes by parameter name, each [lower, upper] for every channel (fit/procedure/search_box.h).
using SearchBounds = std::map<std::string, std::pair<double, double>>;

struct FitSettings {
  // What is minimized.
  std::string procedure;           // a procedure of DESIGN.md §8; empty: a plain fit under `metric`
  std::string metric;              // plain fit: its metric (empty: ngan); with a procedure: an override
  bool per_channel_shape = false;  // one lobe shape per channel instead of one for R, G, B
  int coarsen = 1;                 // widens every metric grid step (1: the papers' grids)
  // hp-2step: a (θh, θd) cell is diffraction-dominated where |det(∇ log ρ, ∇f)| < threshold (seed
  // 004 §4.2's 10⁻²; not scale-free, so a setting: DESIGN.md §8).
  double threshold = 1e-2;

  // How the solver searches (fit/engine).
  int starts = 1;             // start 0 (the scan's best point, or the defaults), then seeded random ones
  std::uint64_t seed = 1;     // of the random starts
  int max_iterations = 100;   // per start and level; a level also ends when it stalls (engine/stall_stop.h)
  // Solve first on every 67th / 17th / 7th sample of the domain, then on all of it
  // (engine/level_schedule.h): the last level alone decides the result.
  bool coarse_to_fine = true;
  // Start 0 is the best point of a scan of the shape parameters' box (engine/start_scan.h), which
  // includes the table's defaults; false: the defaults.
  bool scan_start = true;
  // The user's search box of some parameters, replacing the model's default box (the formula's
  // domain still applies; checked against the model where the fit starts).
  SearchBounds bounds;

  // Ranges a setting accepts.
  static constexpr int kMaxStarts = 1000;
  static constexpr int kMaxIterations = 100000;
  static constexpr int kMaxCoarsen = 20;

  // SettingError naming the first bad setting: an unknown metric, a number out of its range.
  // (The procedure's name is checked where procedures are looked up, fit/procedure/procedure.h.)
  void validate() const;
  // The metric the fit minimizes: `metric`, else the procedure's (passed in), else ngan.
  std::string fitting_metric(const std::string& procedure_metric) const;
};

// One bound as the command line writes it, "NAME=LOWER:UPPER" (`--bounds alpha=0.001:3`);
// SettingError ("bounds") when it is not of that form. validate() checks the numbers.
std::pair<std::string, std::pair<double, double>> parse_search_bound(const std::string& text);

}  // namespace brdfkit::fit
