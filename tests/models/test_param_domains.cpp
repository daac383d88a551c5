// Parameter domains (core/param.h): each parameter's formula domain holds the fitter's box, and
// every model evaluates to finite values at both edges of every parameter's domain (an unbounded
// edge at 10⁶, or 10⁶ × the box's upper edge), the others at their defaults. A domain wider than
// what the model can evaluate fails here.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "brdfkit/core/error.h"
#include "brdfkit/models/model.h"

namespace brdfkit {
namespace {

const std::pair<Vec3d, Vec3d> kPairs[] = {{spherical_direction(0.0, 0.0), spherical_direction(0.0, 0.0)},
                                          {spherical_direction(0.5, 0.0), spherical_direction(0.5, kPi)},
                                          {spherical_direction(1.0, 0.3), spherical_direction(0.4, 2.0)},
                                          {spherical_direction(1.45, 0.0), spherical_direction(1.5, kPi + 0.1)}};

double edge_value(double edge, const ParamSpec& s) {
  if (std::isfinite(edge)) return edge;
  return 1e6 * std::max(1.0, std::abs(s.upper));
}

TEST(ParamDomains, BoxInsideDomainAndEveryModelFiniteAtTheEdges) {
  for (const Model* m : all_models()) {
    const ParamTable& t = m->params();
    for (size_t i = 0; i < t.size(); ++i) {
      const ParamSpec& s = t[i];
      EXPECT_LE(s.valid_lower(), s.lower) << m->name() << " " << s.name;
      EXPECT_GE(s.valid_upper(), s.upper) << m->name() << " " << s.name;
      for (double edge : {s.valid_lower(), s.valid_upper()}) {
        ParamValues v = ParamValues::defaults(t);
        for (auto& ch : v.values) ch[i] = edge_value(edge, s);
        const Brdf b(*m, v);
        for (const auto& [wi, wo] : kPairs) {
          const Rgb r = b.eval(wi, wo);
          EXPECT_TRUE(r.allFinite()) << m->name() << " " << s.name << " = " << v.values[0][i] << ": " << r.transpose();
        }
      }
    }
  }
}

// The examples seed 002's published fits need: values outside the fitter's box, inside the domain.
TEST(ParamDomains, SetAcceptsTheDomainAndNamesItsEdges) {
  const Model& he = model_by_name("he");
  ParamValues v = ParamValues::defaults(he.params());
  v.set(he.params(), "ks", 2.93);
  v.set(he.params(), "sigma0", 8.74);
  v.set(he.params(), "tau", 103.0);
  EXPECT_TRUE(Brdf(he, v).eval(kPairs[1].first, kPairs[1].second).allFinite());
  const Model& laf = model_by_name("lafortune");
  ParamValues l = ParamValues::defaults(laf.params());
  l.set(laf.params(), "N", 16600.0);
  l.set(laf.params(), "ks", 1.71);
  try {
    v.set(he.params(), "sigma0", 11.0);
    FAIL() << "sigma0 = 11 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("parameter 'sigma0': value 11 outside the formula's domain [0.005, 10]"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(l.set(laf.params(), "ks", -0.1), InputError);
}

}  // namespace
}  // namespace brdfkit
