#include "brdfkit/export/glsl_function.h"

#include <fmt/format.h>

#include <cctype>
#include <map>

#include "brdfkit/core/error.h"
#include "brdfkit/fit/fit_record.h"

namespace brdfkit::exporter {
namespace {

// Helpers every model body may call; transcriptions of fresnel/ and ndf/ (cited there).
const char* kHelpers = R"(const float BK_PI = 3.14159265358979323846;
float bk_pow5(float x) { float m = clamp(x, 0.0, 1.0); float m2 = m * m; return m2 * m2 * m; }
// Exact conductor Fresnel of eta + i k (fresnel/conductor.h, Mitsuba 3 fresnel_conductor).
vec3 bk_fresnel_conductor(float c, vec3 eta, vec3 k) {
  c = min(c, 1.0);
  float c2 = c * c, s2 = 1.0 - c2;
  vec3 t0 = eta * eta - k * k - s2;
  vec3 a2b2 = sqrt(t0 * t0 + 4.0 * eta * eta * k * k);
  vec3 a = sqrt(max(0.5 * (a2b2 + t0), 0.0));
  vec3 rs = (a2b2 - 2.0 * a * c + c2) / (a2b2 + 2.0 * a * c + c2);
  vec3 t1 = c2 * a2b2 + s2 * s2, t2 = 2.0 * a * c * s2;
  return 0.5 * (rs + rs * (t1 - t2) / (t1 + t2));
}
// Exact dielectric Fresnel (fresnel/dielectric.h, Cook & Torrance 1982).
float bk_fresnel_dielectric(float c, float eta) {
  c = min(c, 1.0);
  float g2 = eta * eta + c * c - 1.0;
  if (c <= 0.0 || g2 <= 0.0) return 1.0;
  float g = sqrt(g2), a = (g - c) / (g + c), b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
  return 0.5 * a * a * (1.0 + b * b);
}
float bk_ggx_d(float ch, float a) { float a2 = a * a; float t = a2 * ch * ch + (1.0 - ch) * (1.0 + ch); return a2 / (BK_PI * t * t); }
float bk_ggx_g1(float c, float a) { float s2 = 1.0 - c * c; return s2 <= 0.0 ? 1.0 : 2.0 / (1.0 + sqrt(1.0 + a * a * s2 / (c * c))); }
float bk_ggx_lambda(float c, float a) { float s2 = max(1.0 - c * c, 0.0); return (sqrt(1.0 + a * a * s2 / (c * c)) - 1.0) / 2.0; }
float bk_beckmann_d(float ch, float a) { float c2 = ch * ch; return exp(-(1.0 - c2) / (c2 * a * a)) / (BK_PI * a * a * c2 * c2); }
float bk_gtr1(float ch, float a) { float a2 = a * a; return (a2 - 1.0) / (BK_PI * log(a2) * (1.0 + (a2 - 1.0) * ch * ch)); }
)";

// Each body: statements computing ρ for wi, wo above the horizon (checked before), with
// h = normalize(wi + wo), ch = h.z, cd = dot(wi, h) already declared.
constexpr const char* kLambert = R"(  return kd / BK_PI;
)";

constexpr const char* kPbrtDiffuse = R"(  return reflectance / BK_PI;
)";

// models/gltf_metallic_roughness.h
constexpr const char* kGltfMetallicRoughness = R"(  float a = roughness * roughness, a2 = a * a;
  float t = ch * ch * (a2 - 1.0) + 1.0;
  float d = a2 / (BK_PI * t * t);
  float vis = 0.5 / (wo.z * sqrt(a2 + (1.0 - a2) * wi.z * wi.z) + wi.z * sqrt(a2 + (1.0 - a2) * wo.z * wo.z));
  float spec = vis * d;
  float w = bk_pow5(1.0 - cd);
  float r = (ior - 1.0) / (ior + 1.0);
  float f0 = min(r * r * specular_color, 1.0) * specular;
  float f = f0 + (specular - f0) * w;
  vec3 dielectric = f * spec + (1.0 - f) * base_color / BK_PI;
  vec3 metal = (base_color + (1.0 - base_color) * w) * spec;
  return (1.0 - metallic) * dielectric + metallic * metal;
)";

// models/mitsuba_roughconductor.h
constexpr const char* kMitsubaRoughconductorGgx = R"(  float d = bk_ggx_d(ch, alpha);
  if (d * ch <= 1e-20) d = 0.0;
  float g = bk_ggx_g1(wi.z, alpha) * bk_ggx_g1(wo.z, alpha);
  return specular_reflectance * bk_fresnel_conductor(cd, eta, k) * d * g / (4.0 * wi.z * wo.z);
)";

constexpr const char* kMitsubaRoughconductorBeckmann = R"(  float d = bk_beckmann_d(ch, alpha);
  if (d * ch <= 1e-20) d = 0.0;
  float g = 1.0;
  for (int j = 0; j < 2; ++j) {
    float c = j == 0 ? wi.z : wo.z;
    float s2 = 1.0 - c * c;
    if (s2 > 0.0) {
      float a = 1.0 / sqrt(alpha * alpha * s2 / (c * c));
      g *= a >= 1.6 ? 1.0 : (3.535 * a + 2.181 * a * a) / (1.0 + 2.276 * a + 2.577 * a * a);
    }
  }
  return specular_reflectance * bk_fresnel_conductor(cd, eta, k) * d * g / (4.0 * wi.z * wo.z);
)";

// models/mitsuba_principled.h
constexpr const char* kMitsubaPrincipled = R"(  float eta = 2.0 / (1.0 - sqrt(0.08 * specular)) - 1.0;
  float w_d = bk_pow5(1.0 - cd);
  vec3 value = vec3(0.0);
  float f_d = bk_fresnel_dielectric(cd, eta);
  if (f_d > 0.0) {
    float a = max(0.001, roughness * roughness);
    float d = bk_ggx_d(ch, a);
    if (d * ch <= 1e-20) d = 0.0;
    vec3 f = (1.0 - metallic) * f_d + metallic * (base_color + (1.0 - base_color) * w_d);
    value += f * d * bk_ggx_g1(wi.z, a) * bk_ggx_g1(wo.z, a) / (4.0 * wi.z * wo.z);
  }
  if (clearcoat > 0.0) {
    float d_cc = bk_gtr1(ch, mix(0.1, 0.001, clearcoat_gloss));
    value += 0.25 * clearcoat * (0.04 + 0.96 * w_d) * d_cc * bk_ggx_g1(wi.z, 0.25) * bk_ggx_g1(wo.z, 0.25);
  }
  float fo = bk_pow5(1.0 - wo.z), fi = bk_pow5(1.0 - wi.z);
  float f_diff = (1.0 - 0.5 * fi) * (1.0 - 0.5 * fo);
  float rr = 2.0 * roughness * cd * cd;
  float f_retro = rr * (fo + fi + fo * fi * (rr - 1.0));
  float fss = mix(1.0, rr / 2.0, fo) * mix(1.0, rr / 2.0, fi);
  float f_ss = 1.25 * (fss * (1.0 / (wo.z + wi.z) - 0.5) + 0.5);
  value += (1.0 - metallic) * base_color / BK_PI * mix(f_diff + f_retro, f_ss, flatness);
  value += sheen * (1.0 - metallic) * w_d;
  return value;
)";

// models/pbrt_conductor.h, models/pbrt_mix.h
constexpr const char* kPbrtConductor = R"(  float a = sqrt(roughness);
  float g = 1.0 / (1.0 + bk_ggx_lambda(wo.z, a) + bk_ggx_lambda(wi.z, a));
  return bk_ggx_d(ch, a) * bk_fresnel_conductor(cd, eta, k) * g / (4.0 * wi.z * wo.z);
)";

constexpr const char* kPbrtConductorReflectance = R"(  float a = sqrt(roughness);
  vec3 r = min(reflectance, vec3(0.9999));
  float g = 1.0 / (1.0 + bk_ggx_lambda(wo.z, a) + bk_ggx_lambda(wi.z, a));
  return bk_ggx_d(ch, a) * bk_fresnel_conductor(cd, vec3(1.0), 2.0 * sqrt(r) / sqrt(1.0 - r)) * g / (4.0 * wi.z * wo.z);
)";

constexpr const char* kPbrtMixDiffuseConductor = R"(  float a = sqrt(roughness);
  vec3 r = min(conductor_reflectance, vec3(0.9999));
  float g = 1.0 / (1.0 + bk_ggx_lambda(wo.z, a) + bk_ggx_lambda(wi.z, a));
  vec3 conductor = bk_ggx_d(ch, a) * bk_fresnel_conductor(cd, vec3(1.0), 2.0 * sqrt(r) / sqrt(1.0 - r)) * g / (4.0 * wi.z * wo.z);
  return (1.0 - amount) * reflectance / BK_PI + amount * conductor;
)";

// models/disney_principled.h (BRDF Explorer's disney.brdf)
constexpr const char* kDisneyPrincipled = R"(  vec3 cdlin = pow(baseColor, vec3(2.2));
  vec3 cspec0 = mix(vec3(0.08 * specular), cdlin, metallic);
  float fl = bk_pow5(1.0 - wi.z), fv = bk_pow5(1.0 - wo.z), fh = bk_pow5(1.0 - cd);
  float fd90 = 0.5 + 2.0 * cd * cd * roughness;
  float fd = mix(1.0, fd90, fl) * mix(1.0, fd90, fv);
  float fss90 = cd * cd * roughness;
  float fss = mix(1.0, fss90, fl) * mix(1.0, fss90, fv);
  float ss = 1.25 * (fss * (1.0 / (wi.z + wo.z) - 0.5) + 0.5);
  float a = max(0.001, roughness * roughness);
  float gs = 1.0 / (wi.z + sqrt(a * a + wi.z * wi.z - a * a * wi.z * wi.z)) / (wo.z + sqrt(a * a + wo.z * wo.z - a * a * wo.z * wo.z));
  float gr = 1.0 / (wi.z + sqrt(0.0625 + wi.z * wi.z - 0.0625 * wi.z * wi.z)) / (wo.z + sqrt(0.0625 + wo.z * wo.z - 0.0625 * wo.z * wo.z));
  float dr = bk_gtr1(ch, mix(0.1, 0.001, clearcoatGloss));
  return (mix(fd, ss, subsurface) * cdlin / BK_PI + fh * sheen) * (1.0 - metallic) + gs * mix(cspec0, vec3(1.0), fh) * bk_ggx_d(ch, a)
         + 0.25 * clearcoat * gr * mix(0.04, 1.0, fh) * dr;
)";

// models/cook_torrance.h with Schlick F and uncorrelated Smith G (closed-form Λ)
constexpr const char* kCookTorranceGgx = R"(  vec3 f = F0 + (1.0 - F0) * bk_pow5(1.0 - cd);
  float g = bk_ggx_g1(wi.z, alpha) * bk_ggx_g1(wo.z, alpha);
  return kd / BK_PI + ks * f * bk_ggx_d(ch, alpha) * g / (4.0 * wi.z * wo.z);
)";

// Model name → its body; the models listed are the ones with a GLSL form.
const std::map<std::string, const char*>& bodies() {
  static const std::map<std::string, const char*> m = {
      {"lambert", kLambert},
      {"pbrt-diffuse", kPbrtDiffuse},
      {"gltf-metallic-roughness", kGltfMetallicRoughness},
      {"mitsuba-roughconductor-ggx", kMitsubaRoughconductorGgx},
      {"mitsuba-roughconductor-beckmann", kMitsubaRoughconductorBeckmann},
      {"mitsuba-principled", kMitsubaPrincipled},
      {"pbrt-conductor", kPbrtConductor},
      {"pbrt-conductor-reflectance", kPbrtConductorReflectance},
      {"pbrt-mix-diffuse-conductor", kPbrtMixDiffuseConductor},
      {"disney-principled", kDisneyPrincipled},
      {"cook-torrance-ggx", kCookTorranceGgx},
  };
  return m;
}

}  // namespace

std::vector<std::string> glsl_models() {
  std::vector<std::string> out;
  for (const auto& [name, body] : bodies()) out.push_back(name);
  return out;
}

std::string glsl_name(const std::string& param) {
  std::string out;
  for (char c : param) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  if (out.empty() || std::isdigit(static_cast<unsigned char>(out[0]))) out = "p" + out;
  return out;
}

std::string glsl_float(double x) {
  std::string s = fmt::format("{:.9g}", x);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::string glsl_functions(const Model& model) {
  const auto it = bodies().find(std::string(model.name()));
  if (it == bodies().end()) {
    std::string known;
    for (const std::string& n : glsl_models()) known += (known.empty() ? "" : ", ") + n;
    throw InputError("model '" + std::string(model.name()) + "'", "has no GLSL form yet; models with one: " + known +
                                                                   " (refit into one of them, e.g. --to gltf)");
  }
  return std::string(kHelpers) + "vec3 brdfkit_brdf(vec3 wi, vec3 wo) {\n" +
         "  if (wi.z <= 0.0 || wo.z <= 0.0) return vec3(0.0);\n" +
         "  vec3 h = normalize(wi + wo);\n  float ch = h.z, cd = dot(wi, h);\n" + it->second + "}\n" +
         "vec3 brdfkit_brdf(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) {\n"
         "  return brdfkit_brdf(vec3(dot(L, X), dot(L, Y), dot(L, N)), vec3(dot(V, X), dot(V, Y), dot(V, N)));\n}\n";
}

std::string glsl_constants(const Brdf& brdf) {
  const ParamTable& t = brdf.model().params();
  if (fit::shape_differs_by_channel(brdf.model(), brdf.values()))
    throw InputError("GLSL export", "a fit with a per-channel shape has no GLSL form (one float per shared parameter)");
  const auto& v = brdf.values().values;
  std::string out;
  for (size_t i = 0; i < t.size(); ++i) {
    if (t[i].scope == Scope::Shared)
      out += fmt::format("const float {} = {};\n", glsl_name(t[i].name), glsl_float(v[0][i]));
    else
      out += fmt::format("const vec3 {} = vec3({}, {}, {});\n", glsl_name(t[i].name), glsl_float(v[0][i]),
                         glsl_float(v[1][i]), glsl_float(v[2][i]));
  }
  return out;
}

std::string glsl_file(const Brdf& brdf, const Provenance& p) {
  std::string out = "// brdfkit_brdf(wi, wo): rho in 1/sr per RGB channel, local frame n = +z, no cosine.\n";
  for (const std::string& line : provenance_lines(p)) out += "// " + line + "\n";
  return out + glsl_constants(brdf) + glsl_functions(brdf.model());
}

}  // namespace brdfkit::exporter
