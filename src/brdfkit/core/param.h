#pragma once
// A model's parameter table: the one description that fitting, the CLI, JSON and Python read.
#include <array>
#include <string>
#include <vector>

namespace brdfkit {

enum class Scope {
  PerChannel,  // one value per RGB channel (colours, Fresnel F0 …)
  Shared,      // one value for R, G and B (lobe shapes by default)
};

struct ParamSpec {
  std::string name;  // the paper's name: "kd", "alpha", "p", "eta" — never "roughness"
  double lower;
  double upper;
  double def;
  Scope scope;
  bool linear;       // ρ is linear in it with the others fixed (colour scales): variable projection
  std::string doc;   // one line: meaning and source
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
