// Directional albedo of the seed 002 / seed 003 models at their parameter bounds: finite
// (no NaN, no overflow) everywhere, and which models can reflect more than they receive.
// Colour parameters at their upper bound, each shape parameter at its lower and upper bound.
#include <gtest/gtest.h>

#include "support/mc_albedo.h"

namespace brdfkit {
namespace {

TEST(ClassicModels, AlbedoFiniteAtParameterBounds) {
  const char* names[] = {"ward",      "ward-aniso",        "ward-duer",
                         "blinn-phong", "lafortune",       "lafortune-2",
                         "ashikhmin-shirley", "ashikhmin-shirley-dielectric", "low-smooth",
                         "low-smooth-2"};
  for (const char* name : names) {
    const Model& m = model_by_name(name);
    const ParamTable& t = m.params();
    double worst = 0;
    std::string worst_where;
    // Corner sets: all shape parameters low, all high, then each one flipped alone.
    std::vector<std::vector<double>> sets;
    auto base = [&](bool high) {
      std::vector<double> v;
      for (const auto& s : t) v.push_back(s.linear ? (s.name == "kd" ? 0.0 : s.upper) : (high ? s.upper : s.lower));
      return v;
    };
    sets.push_back(base(false));
    sets.push_back(base(true));
    for (size_t i = 0; i < t.size(); ++i)
      if (!t[i].linear) {
        auto v = base(false);
        v[i] = t[i].upper;
        sets.push_back(v);
        v = base(true);
        v[i] = t[i].lower;
        sets.push_back(v);
      }
    for (const auto& v : sets)
      for (double deg : {0.0, 45.0, 80.0, 89.0}) {
        const double a = test::mc_albedo(m, v.data(), 0, deg * kPi / 180, 32);
        std::string where = std::string(name) + " theta " + std::to_string(int(deg)) + " {";
        for (size_t i = 0; i < t.size(); ++i) where += t[i].name + "=" + std::to_string(v[i]) + " ";
        where += "}";
        ASSERT_TRUE(std::isfinite(a) && a >= 0) << where << " albedo " << a;
        if (a > worst) worst = a, worst_where = where;
      }
    std::cout << "[ albedo   ] " << name << " max over bounds " << worst << " at " << worst_where << "\n";
  }
}

}  // namespace
}  // namespace brdfkit
