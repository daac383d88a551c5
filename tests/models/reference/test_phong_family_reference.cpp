// The cosine-power lobes of the catalogue against their papers' equations as DESIGN.md §6 writes
// them, transcribed here, plus closed-form albedos at normal incidence:
//   blinn-phong   kd/π + ks (N+2)/(8π) cosᴺθh                          (brdfkit's constant, DESIGN.md §6)
//   lafortune(-2) kd/π + Σ ks (N+2)/(2π m^N) max(0, Cxy(ux vx + uy vy) + Cz uz vz)^N, m = max(|Cxy|, |Cz|)
//                                                                     (Lafortune 1997 Eq. 6, Ngan's normalization)
//   ashikhmin-shirley(-dielectric, -ngan2005)  kd/π + sqrt((nu+1)(nv+1))/(8π) (n·h)^{nu cos²φh + nv sin²φh}
//                   / ((h·k) max(n·k1, n·k2)) F(k·h), nu = nv = N     (Ashikhmin & Shirley 2000 Eq. 4)
// Every term is closed-form: bound 1e-10 relative (1e-12 on the albedos).
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "brdfkit/models/model.h"
#include "reference_fresnel.h"
#include "reference_lobes.h"
#include "reference_pairs.h"

namespace brdfkit::test::ref {
namespace {

const std::vector<Setting> kDiffuse = {{"kd", 0.25, 0}, {"kd", 0.1, 1}, {"kd", 0.0, 2}};

TEST(PhongFamilyReference, BlinnPhongLobe) {
  const Model& m = model_by_name("blinn-phong");
  for (double n : {3.5, 40.0, 2000.0}) {
    std::vector<Setting> s = kDiffuse;
    s.insert(s.end(), {{"ks", 0.4, 0}, {"ks", 0.7, 1}, {"ks", 0.9, 2}, {"N", n}});
    const ParamValues v = values_of(m, s);
    auto reference = [&m, v](double norm) -> Reference {
      return [&m, v, norm](int c, const Vec3d& wi, const Vec3d& wo) {
        return param(m, v, "kd", c) / kPi + param(m, v, "ks", c) * blinn_phong_lobe(wi, wo, param(m, v, "N", c), norm);
      };
    };
    const std::string label = "N=" + std::to_string(n);
    expect_matches_reference(m, v, reference(kBlinnPhongNorm), 1e-10, label);
    expect_detects_five_percent(m, v, reference(kBlinnPhongNorm / 1.05), 1e-10, label);
  }
}

Reference lafortune_reference(const Model& m, const ParamValues& v, int lobes, double norm = kLafortuneNorm) {
  return [&m, v, lobes, norm](int c, const Vec3d& wi, const Vec3d& wo) {
    double sum = param(m, v, "kd", c) / kPi;
    for (int j = 1; j <= lobes; ++j) {
      const std::string s = lobes == 1 ? "" : std::to_string(j);
      sum += param(m, v, "ks" + s, c) *
             lafortune_lobe(wi, wo, param(m, v, "Cxy" + s, c), param(m, v, "Cz" + s, c), param(m, v, "N" + s, c), norm);
    }
    return sum;
  };
}

TEST(PhongFamilyReference, LafortuneOneLobe) {
  const Model& m = model_by_name("lafortune");
  struct Shape { double cxy, cz, n; };
  // A mirror lobe, an off-specular one (|Cxy| > |Cz|) and a forward/retro one with Cxy > 0.
  for (Shape sh : {Shape{-1.0, 0.95, 25}, Shape{-0.8, 0.6, 7.3}, Shape{0.3, 1.0, 3}}) {
    std::vector<Setting> s = kDiffuse;
    s.insert(s.end(), {{"ks", 0.5, 0}, {"ks", 0.3, 1}, {"ks", 0.8, 2}, {"Cxy", sh.cxy}, {"Cz", sh.cz}, {"N", sh.n}});
    const ParamValues v = values_of(m, s);
    const std::string label = "Cxy=" + std::to_string(sh.cxy) + " N=" + std::to_string(sh.n);
    expect_matches_reference(m, v, lafortune_reference(m, v, 1), 1e-10, label);
    expect_detects_five_percent(m, v, lafortune_reference(m, v, 1, kLafortuneNorm / 1.05), 1e-10, label);
  }
}

TEST(PhongFamilyReference, LafortuneTwoLobes) {
  const Model& m = model_by_name("lafortune-2");
  // A sharp mirror lobe with a wide one; an off-specular lobe with a retro-reflective one (Cxy > 0).
  const std::vector<std::vector<Setting>> sets = {
      {{"kd", 0.1}, {"ks1", 0.4, 0}, {"ks1", 0.6, 1}, {"ks1", 0.2, 2}, {"Cxy1", -1.0}, {"Cz1", 0.9}, {"N1", 60},
       {"ks2", 0.3}, {"Cxy2", -0.5}, {"Cz2", 1.0}, {"N2", 4.5}},
      {{"kd", 0.0}, {"ks1", 0.7}, {"Cxy1", -0.9}, {"Cz1", 0.4}, {"N1", 12.5}, {"ks2", 0.2, 0}, {"ks2", 0.05, 1},
       {"ks2", 0.4, 2}, {"Cxy2", 0.6}, {"Cz2", 0.8}, {"N2", 9}}};
  for (size_t k = 0; k < sets.size(); ++k) {
    const ParamValues v = values_of(m, sets[k]);
    const std::string label = "two lobes, set " + std::to_string(k + 1);
    expect_matches_reference(m, v, lafortune_reference(m, v, 2), 1e-10, label);
    expect_detects_five_percent(m, v, lafortune_reference(m, v, 2, kLafortuneNorm / 1.05), 1e-10, label);
  }
}

TEST(PhongFamilyReference, AshikhminShirleySchlick) {
  const Model& m = model_by_name("ashikhmin-shirley");
  for (double n : {8.0, 80.0, 1000.0}) {
    std::vector<Setting> s = kDiffuse;
    s.insert(s.end(), {{"Rs", 0.05, 0}, {"Rs", 0.5, 1}, {"Rs", 0.9, 2}, {"N", n}});
    const ParamValues v = values_of(m, s);
    auto reference = [&m, v](double norm) -> Reference {
      return [&m, v, norm](int c, const Vec3d& wi, const Vec3d& wo) {
        const double nn = param(m, v, "N", c);
        return param(m, v, "kd", c) / kPi + ashikhmin_lobe(wi, wo, nn, nn, norm) *
                                                schlick(param(m, v, "Rs", c), wi.dot(half_vector(wi, wo)));
      };
    };
    const std::string label = "N=" + std::to_string(n);
    expect_matches_reference(m, v, reference(kAshikhminNorm), 1e-10, label);
    expect_detects_five_percent(m, v, reference(kAshikhminNorm / 1.05), 1e-10, label);
  }
}

TEST(PhongFamilyReference, AshikhminShirleyDielectric) {
  const Model& m = model_by_name("ashikhmin-shirley-dielectric");
  for (double n : {12.0, 600.0}) {
    std::vector<Setting> s = kDiffuse;
    s.insert(s.end(), {{"ks", 1.0, 0}, {"ks", 0.5, 1}, {"ks", 1.8, 2}, {"N", n}, {"eta", 1.6}});
    const ParamValues v = values_of(m, s);
    auto reference = [&m, v](double norm) -> Reference {
      return [&m, v, norm](int c, const Vec3d& wi, const Vec3d& wo) {
        const double nn = param(m, v, "N", c);
        return param(m, v, "kd", c) / kPi +
               param(m, v, "ks", c) * ashikhmin_lobe(wi, wo, nn, nn, norm) *
                   fresnel_dielectric(wi.dot(half_vector(wi, wo)), param(m, v, "eta", c));
      };
    };
    const std::string label = "N=" + std::to_string(n);
    expect_matches_reference(m, v, reference(kAshikhminNorm), 1e-10, label);
    expect_detects_five_percent(m, v, reference(kAshikhminNorm / 1.05), 1e-10, label);
  }
}

// Seed 002's form: a specular colour ks per channel times one lobe shape with one Schlick F0.
TEST(PhongFamilyReference, AshikhminShirleyNgan) {
  const Model& m = model_by_name("ashikhmin-shirley-ngan2005");
  for (double n : {12.0, 600.0}) {
    std::vector<Setting> s = kDiffuse;
    s.insert(s.end(), {{"ks", 0.04, 0}, {"ks", 0.3, 1}, {"ks", 0.9, 2}, {"N", n}, {"F0", 0.2}});
    const ParamValues v = values_of(m, s);
    auto reference = [&m, v](double norm) -> Reference {
      return [&m, v, norm](int c, const Vec3d& wi, const Vec3d& wo) {
        const double nn = param(m, v, "N", c);
        return param(m, v, "kd", c) / kPi + param(m, v, "ks", c) * ashikhmin_lobe(wi, wo, nn, nn, norm) *
                                                schlick(param(m, v, "F0", c), wi.dot(half_vector(wi, wo)));
      };
    };
    const std::string label = "N=" + std::to_string(n);
    expect_matches_reference(m, v, reference(kAshikhminNorm), 1e-10, label);
    expect_detects_five_percent(m, v, reference(kAshikhminNorm / 1.05), 1e-10, label);
  }
}

// a(wi) = ∫ ρ(wi, wo) cosθo dωo of the model at wi = n, by Gauss-Legendre in cosθo (exact for the
// polynomial integrands below) times a midpoint rule in φo (the integrands do not depend on φo).
double albedo_at_normal_incidence(const Model& m, const ParamValues& v, int c) {
  const Vec3d wi(0, 0, 1);
  const int n_phi = 8;
  double sum = 0;
  for (int k = 0; k < n_phi; ++k) {
    const double phi = (k + 0.5) * 2 * kPi / n_phi;
    sum += boost::math::quadrature::gauss<double, 40>::integrate(
        [&](double mu) {
          const double s = std::sqrt(std::max(0.0, 1 - mu * mu));
          return m.eval(v.channel(c), c, wi, Vec3d(s * std::cos(phi), s * std::sin(phi), mu)) * mu;
        },
        0.0, 1.0);
  }
  return 2 * kPi * sum / n_phi;
}

// Lafortune's mirror lobe (Cxy = −1, Cz = 1) at normal incidence is ks (N+2)/(2π) cosᴺθo: its
// albedo is ks (N+2)/(2π) · 2π/(N+2) = ks, whatever N.
TEST(PhongFamilyReference, LafortuneMirrorLobeAlbedoIsKs) {
  const Model& m = model_by_name("lafortune");
  for (double n : {2.0, 20.0, 50.0}) {
    const ParamValues v = values_of(m, {{"kd", 0.0}, {"ks", 0.37}, {"Cxy", -1.0}, {"Cz", 1.0}, {"N", n}});
    EXPECT_NEAR(albedo_at_normal_incidence(m, v, 0), 0.37, 1e-12) << "N " << n;
  }
}

// Blinn-Phong at normal incidence: θh = θo/2; with u = cos²(θo/2) the albedo is
// ks (N+2)/2 ∫_{1/2}^{1} u^{N/2} (2u − 1) du
//   = ks (N+2)/2 [4/(N+4) (1 − 2^{−(N/2+2)}) − 2/(N+2) (1 − 2^{−(N/2+1)})]   (→ ks for large N).
TEST(PhongFamilyReference, BlinnPhongAlbedoAtNormalIncidence) {
  const Model& m = model_by_name("blinn-phong");
  for (double n : {2.0, 10.0, 40.0}) {
    const ParamValues v = values_of(m, {{"kd", 0.0}, {"ks", 0.6}, {"N", n}});
    const double closed = 0.6 * (n + 2) / 2 *
                          (4 / (n + 4) * (1 - std::pow(2.0, -(n / 2 + 2))) - 2 / (n + 2) * (1 - std::pow(2.0, -(n / 2 + 1))));
    EXPECT_NEAR(albedo_at_normal_incidence(m, v, 0), closed, 1e-12) << "N " << n;
  }
}

}  // namespace
}  // namespace brdfkit::test::ref
