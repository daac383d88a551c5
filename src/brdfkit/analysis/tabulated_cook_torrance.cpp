#include "brdfkit/analysis/tabulated_cook_torrance.h"

#include <algorithm>
#include <cmath>

#include "brdfkit/core/error.h"
#include "brdfkit/core/warp.h"
#include "brdfkit/fresnel/schlick.h"

namespace brdfkit::analysis {

namespace {
constexpr int kKd = 0, kKs = 1, kF0 = 2;

ParamTable make_table() {
  ParamTable t = {
      {"kd", 0.0, 1.0, 0.2, Scope::PerChannel, true, "diffuse albedo of the Lambertian term kd/pi (DESIGN.md §6)"},
      {"ks", 0.0, 100.0, 0.5, Scope::PerChannel, true, "specular scale in ks F D G/(4 cos_i cos_o) (seed 004 Eq. 1)"}};
  for (auto& s : SchlickFresnel<double>::params()) t.push_back(s);
  return t;
}

// Probability of the specular lobe, as CookTorrance::specular_probability (seed 004 §5.5).
double specular_probability(const double* p, const Vec3d& wo) {
  const double d = std::max(0.0, p[kKd]);
  const double s = std::max(0.0, p[kKs] * SchlickFresnel<double>(p + kF0).eval(wo.z()));
  if (!(d + s > 0) || !std::isfinite(d + s)) return 0.5;
  return s / (d + s);
}
}  // namespace

TabulatedCookTorrance::TabulatedCookTorrance(std::vector<double> theta, std::vector<double> d)
    : table_(make_table()), ndf_(std::move(theta), std::move(d)) {
  const Tabulated<double>& ndf = ndf_;
  masking_ = ProjectedAreaMasking([&ndf](double c) { return ndf.D(c); }, ndf_.theta);
}

std::string_view TabulatedCookTorrance::description() const {
  return "kd/pi + ks F D G/(4 cos_i cos_o): tabulated D estimated from data (Ngan 2005 5.1), Schlick F, Smith G";
}

double TabulatedCookTorrance::specular_shape(const Vec3d& wi, const Vec3d& wo) const {
  if (!(wi.z() > 0 && wo.z() > 0)) return 0.0;
  const Vec3d h = (wi + wo).normalized();
  return ndf_.D(h.z()) * masking_.g1(wi.z()) * masking_.g1(wo.z()) / (4 * wi.z() * wo.z());
}

double TabulatedCookTorrance::eval(const double* p, int, const Vec3d& wi, const Vec3d& wo) const {
  if (!(wi.z() > 0 && wo.z() > 0)) return 0.0;
  const double cd = 0.5 * (wi + wo).norm();  // |wi + wo| = 2 cosθd for unit directions
  return p[kKd] * kInvPi + p[kKs] * SchlickFresnel<double>(p + kF0).eval(cd) * specular_shape(wi, wo);
}

std::optional<Vec3d> TabulatedCookTorrance::sample(const double* p, int, const Vec3d& wo, const Vec2d& u,
                                                   double u_lobe) const {
  if (!(wo.z() > 0)) return std::nullopt;
  if (!(u_lobe < specular_probability(p, wo))) {
    const Vec3d wi = square_to_cosine_hemisphere(u);
    if (!(wi.z() > 0)) return std::nullopt;
    return wi;
  }
  const Vec3d m = ndf_.sample(u);
  if (!(wo.dot(m) > 0)) return std::nullopt;
  const Vec3d wi = reflect(wo, m);
  if (!(wi.z() > 0)) return std::nullopt;
  return wi;
}

double TabulatedCookTorrance::pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) const {
  if (!(wo.z() > 0 && wi.z() > 0)) return 0.0;
  const double ps = specular_probability(p, wo);
  double v = (1.0 - ps) * wi.z() * kInvPi;
  const Vec3d sum = wi + wo;
  const double len = sum.norm();
  if (ps > 0 && len > 0) {
    const Vec3d h = sum / len;
    const double oh = wo.dot(h);
    if (oh > 0) v += ps * ndf_.pdf(h) / (4.0 * oh);  // half-vector Jacobian (DESIGN.md §6)
  }
  return v;
}

nlohmann::json TabulatedCookTorrance::table_json() const {
  return {{"theta", ndf_.theta}, {"D", ndf_.value}};
}

TabulatedCookTorrance TabulatedCookTorrance::from_table_json(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object() || !j.contains("theta") || !j.contains("D") || !j["theta"].is_array() || !j["D"].is_array())
    throw InputError(where, "expected an object with arrays 'theta' and 'D'");
  std::vector<double> t, d;
  for (const auto& v : j["theta"]) {
    if (!v.is_number()) throw InputError(where, "'theta' holds a non-number");
    t.push_back(v.get<double>());
  }
  for (const auto& v : j["D"]) {
    if (!v.is_number()) throw InputError(where, "'D' holds a non-number");
    d.push_back(v.get<double>());
  }
  return TabulatedCookTorrance(std::move(t), std::move(d));
}

}  // namespace brdfkit::analysis
