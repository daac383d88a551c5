#pragma once
// A model's parameter table: the one description that fitting, the CLI, JSON and Python read.
#include <array>
#include <limits>
#include <string>
#include <vector>

namespace brdfkit {

enum class Scope {
  PerChannel,  // one value per RGB channel (colours, Fresnel F0 …)
  Shared,      // one value for R, G and B (lobe shapes by default)
};

// An unbounded domain edge (ParamSpec::domain_upper).
inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

struct ParamSpec {
  std::string name;  // the paper's name: "kd", "alpha", "p", "eta" — never "roughness"
  double lower;
  double upper;
  double def;
  Scope scope;
  bool linear;       // ρ is linear in it with the others fixed (colour scales): variable projection
  std::string doc;   // one line: meaning and source
  // [lower, upper] is the box the fitter searches; the formula is defined on a wider domain, which
  // is what eval, tabulate, render, error and loaded fits accept (published values lie outside
  // boxes). Unset (NaN): the box's edge, except a colour scale's upper edge (linear, lower 0),
  // which is ∞: ρ is linear in it.
  double domain_lower = std::numeric_limits<double>::quiet_NaN();
  double domain_upper = std::numeric_limits<double>::quiet_NaN();

  double valid_lower() const;
  double valid_upper() const;
  bool in_domain(double x) const { return x >= valid_lower() && x <= valid_upper(); }
};

using ParamTable = std::vector<ParamSpec>;

// Values of every parameter for each channel: values[c][i] is parameter i for channel c.
// Shared parameters hold the same value in all three channels.
struct ParamValues {
  std::array<std::vector<double>, 3> values;

  static ParamValues defaults(const ParamTable& table);
  // Sets parameter `name` (all channels) or `name[c]`; throws InputError on unknown names.
  void set(const ParamTable& table, const std::string& name, double value, int channel = -1);
  const double* channel(int c) const { return values[c].data(); }
};

// Index of a parameter by name, or -1.
int find_param(const ParamTable& table, const std::string& name);

}  // namespace brdfkit
