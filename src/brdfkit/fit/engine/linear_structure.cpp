#include "brdfkit/fit/engine/linear_structure.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "brdfkit/core/error.h"

namespace brdfkit::fit {

std::pair<Vec3d, Vec3d> probe_pair(int k) {
  return {spherical_direction(0.05 + 0.09 * k, 0.0), spherical_direction(0.1 + 0.08 * k, 0.4 * k)};
}

namespace {

// Whether ρ vanishes with every colour at 0, at the defaults.
bool homogeneous(const Model& model, const std::vector<int>& colours) {
  const ParamValues pv = ParamValues::defaults(model.params());
  for (int c = 0; c < 3; ++c) {
    std::vector<double> p = pv.values[size_t(c)];
    for (int l : colours) p[size_t(l)] = 0.0;
    for (int k = 0; k < kProbePairs; ++k) {
      const auto [wi, wo] = probe_pair(k);
      if (model.eval(p.data(), c, wi, wo) != 0.0) return false;
    }
  }
  return true;
}

// Whether P rides on colour L: ρ affine in P with L = 1 (others 0), unchanged by P with L = 0
// (others 1), and P changes something.
bool rides_on(const Model& model, const std::vector<int>& colours, size_t P, int L) {
  const ParamTable& table = model.params();
  const ParamSpec& s = table[P];
  const ParamValues defaults = ParamValues::defaults(table);
  bool depends = false;
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < kProbePairs; ++k) {
      const auto [wi, wo] = probe_pair(k);
      auto at = [&](double l_value, double others, double p_value) {
        std::vector<double> p = defaults.values[size_t(c)];
        for (int l : colours) p[size_t(l)] = others;
        p[size_t(L)] = l_value;
        p[P] = p_value;
        return model.eval(p.data(), c, wi, wo);
      };
      const double a = at(1, 0, s.lower), b = at(1, 0, s.upper), mid = at(1, 0, 0.5 * (s.lower + s.upper));
      if (!(std::abs(mid - 0.5 * (a + b)) <= kAffineTolerance * (std::abs(a) + std::abs(b)) + 1e-300)) return false;
      depends = depends || a != b;
      if (at(0, 1, s.lower) != at(0, 1, s.upper)) return false;
    }
  return depends;
}

std::vector<int> pair_affine_parameters(const Model& model, const std::vector<int>& colours) {
  const ParamTable& table = model.params();
  std::vector<int> paired(table.size(), -1);
  for (size_t P = 0; P < table.size(); ++P) {
    const ParamSpec& s = table[P];
    if (s.linear || s.scope != Scope::PerChannel || !(s.upper > s.lower) || !std::isfinite(s.lower) ||
        !std::isfinite(s.upper))
      continue;
    for (int L : colours) {
      if (table[size_t(L)].lower != 0.0 || std::count(paired.begin(), paired.end(), L)) continue;
      if (rides_on(model, colours, P, L)) {
        paired[P] = L;
        break;
      }
    }
  }
  return paired;
}

}  // namespace

LinearStructure probe_linear_structure(const Model& model, bool pair_affine) {
  const ParamTable& table = model.params();
  LinearStructure s;
  for (size_t p = 0; p < table.size(); ++p)
    if (table[p].linear && table[p].scope == Scope::PerChannel) s.colours.push_back(int(p));
  if (!homogeneous(model, s.colours)) s.colours.clear();
  s.paired = pair_affine && !s.colours.empty() ? pair_affine_parameters(model, s.colours)
                                               : std::vector<int>(table.size(), -1);
  for (int l : s.colours) {
    const auto it = std::find(s.paired.begin(), s.paired.end(), l);
    if (it == s.paired.end()) {
      s.bases.push_back({l});
      continue;
    }
    const int affine = int(it - s.paired.begin());
    s.bases.push_back({l, affine, table[size_t(affine)].lower});
    s.bases.push_back({l, affine, table[size_t(affine)].upper});
  }
  if (pair_affine && s.bases.size() > kMaxBases)
    throw InputError("model '" + std::string(model.name()) + "'", "more than 6 linear parameters");
  return s;
}

std::vector<bool> solved_inside(const LinearStructure& s, bool project) {
  std::vector<bool> out(s.paired.size(), false);
  if (!project) return out;
  for (int l : s.colours) out[size_t(l)] = true;
  for (size_t p = 0; p < s.paired.size(); ++p) out[p] = out[p] || s.paired[p] >= 0;
  return out;
}

std::vector<double> basis_params(const ParamValues& pv, int c, const std::vector<LinearBasis>& bases, size_t j) {
  std::vector<double> p = pv.values[size_t(c)];
  for (const LinearBasis& b : bases) p[size_t(b.lin)] = 0.0;
  p[size_t(bases[j].lin)] = 1.0;
  if (bases[j].affine >= 0) p[size_t(bases[j].affine)] = bases[j].affine_value;
  return p;
}

bool basis_independent_of_shape(const Model& model, const SolverVariables& vars, const std::vector<LinearBasis>& bases,
                                size_t j, int classes) {
  const ParamValues pv = ParamValues::defaults(model.params());
  auto is_colour = [&](int param) {
    return std::any_of(bases.begin(), bases.end(), [&](const LinearBasis& b) { return b.lin == param; });
  };
  for (int c = 0; c < classes; ++c) {
    const std::vector<double> a = basis_params(pv, c, bases, j);
    std::vector<double> b = a;
    for (size_t v = 0; v < vars.size(); ++v) {
      const ParamSpec& s = vars.spec(v);
      if (vars[v].affects(c) && !is_colour(vars[v].param))
        b[size_t(vars[v].param)] = s.lower + kShapeProbeFraction * (s.upper - s.lower);
    }
    for (int k = 0; k < kProbePairs; ++k) {
      const auto [wi, wo] = probe_pair(k);
      if (model.eval(a.data(), c, wi, wo) != model.eval(b.data(), c, wi, wo)) return false;
    }
  }
  return true;
}

bool same_in_every_channel(const Model& model, const std::vector<double>& p) {
  for (int k = 0; k < kChannelProbePairs; ++k) {
    const auto [wi, wo] = probe_pair(k);
    const double v0 = model.eval(p.data(), 0, wi, wo);
    for (int c = 1; c < 3; ++c)
      if (model.eval(p.data(), c, wi, wo) != v0) return false;
  }
  return true;
}

}  // namespace brdfkit::fit
