#include "brdfkit/fit/engine/start_scan.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "brdfkit/fit/engine/sample_stride.h"

namespace brdfkit::fit {

namespace {

constexpr int kLinearPoints = 8;
constexpr double kPointsPerDecade = 4;  // a width step of 10^¼ ≈ 1.78: the solver's basin is wider
constexpr int kMaxLogPoints = 24;
// A log-scanned parameter whose lower bound is 0 (exponents N ∈ [0, 1e6]) is scanned from
// upper · kZeroLowerSpan: below that the lobe is flat to within the data's noise.
constexpr double kZeroLowerSpan = 1e-6;

}  // namespace

std::vector<double> scan_grid(const ParamSpec& s) {
  std::vector<double> out;
  if (!std::isfinite(s.lower) || !std::isfinite(s.upper) || !(s.upper > s.lower)) return out;
  double lo = s.lower;
  const bool log_scale = (s.lower > 0 && s.upper / s.lower >= kLogSpan) || (s.lower == 0 && s.upper >= kLogSpan);
  if (!log_scale) {
    for (int i = 0; i < kLinearPoints; ++i) out.push_back(s.lower + (i + 0.5) / kLinearPoints * (s.upper - s.lower));
    return out;
  }
  if (lo == 0) lo = s.upper * kZeroLowerSpan;
  const double decades = std::log10(s.upper / lo);
  const int n = std::clamp(int(std::lround(kPointsPerDecade * decades)), kLinearPoints, kMaxLogPoints);
  for (int i = 0; i < n; ++i) out.push_back(lo * std::pow(s.upper / lo, (i + 0.5) / n));
  return out;
}

std::size_t scan_stride(std::size_t samples) { return coprime_stride(samples / 20000); }

StartScan scan_start(const ParamTable& table, const std::vector<int>& var_param, const std::vector<double>& start,
                     const std::function<double(const std::vector<double>&)>& cost, int sweeps) {
  StartScan best{start, cost(start), 1};
  if (!std::isfinite(best.cost)) best.cost = std::numeric_limits<double>::infinity();
  // The groups of variables to scan, in table order: each parameter's variables together, then,
  // for a per-channel parameter, each of them alone.
  std::vector<std::vector<size_t>> groups;
  std::vector<std::vector<double>> grids;
  for (size_t p = 0; p < table.size(); ++p) {
    std::vector<size_t> vars;
    for (size_t v = 0; v < var_param.size(); ++v)
      if (var_param[v] == int(p)) vars.push_back(v);
    const std::vector<double> grid = scan_grid(table[p]);
    if (vars.empty() || grid.empty()) continue;
    groups.push_back(vars);
    grids.push_back(grid);
    if (vars.size() > 1)
      for (size_t v : vars) {
        groups.push_back({v});
        grids.push_back(grid);
      }
  }
  // One parameter: a second sweep would repeat the first.
  if (groups.size() == 1) sweeps = std::min(sweeps, 1);
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    bool improved = false;
    for (size_t g = 0; g < groups.size(); ++g) {
      std::vector<double> x = best.x;
      StartScan round = best;
      for (double value : grids[g]) {
        for (size_t v : groups[g]) x[v] = value;
        const double c = cost(x);
        ++best.points;
        if (c < round.cost) {  // NaN and +inf never win
          round.cost = c;
          round.x = x;
        }
      }
      if (round.cost < best.cost) {
        best.cost = round.cost;
        best.x = round.x;
        improved = true;
      }
    }
    if (!improved) break;
  }
  return best;
}

}  // namespace brdfkit::fit
