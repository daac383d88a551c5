#include "brdfkit/models/published_fits.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "brdfkit/core/error.h"
#include "brdfkit/models/bbm_fit_text.h"
#include "brdfkit/fresnel/bagher_fresnel.h"
#include "brdfkit/fresnel/dielectric.h"
#include "brdfkit/models/cook_torrance.h"
#include "brdfkit/models/microfacet_model.h"
#include "brdfkit/models/named_model.h"
#include "brdfkit/ndf/beckmann.h"
#include "brdfkit/ndf/sgd.h"

namespace brdfkit {

namespace {

using LowCookTorrance =
    Named<CookTorrance<Beckmann, DielectricFresnel, Masking::VGroove>, "cook-torrance-low2012",
          "kd/pi + ks F D G/(4 cos_i cos_o): Beckmann D, dielectric F(eta), V-groove G (Low 2012's published fits)">;

using BagherSgd =
    Named<CookTorrance<Sgd, BagherFresnel>, "cook-torrance-sgd-bagher2012",
          "kd/pi + ks F D G/(4 cos_i cos_o): SGD D, Bagher F0/F1 Fresnel, Smith G (Bagher 2012's published fits)">;

// Ngan 2005's lobes (models/bbm_fit_text.h) and the brdfkit model of the same formula.
const std::map<std::string, std::string> kNganModels = {
    {"NganWard", "ward"},
    {"NganWardDuer", "ward-duer"},
    {"NganLafortune", "lafortune"},
    {"NganCookTorrance", "cook-torrance"},
    {"NganAshikhminShirley", "ashikhmin-shirley-ngan2005"},
    {"NganBlinnPhong", "blinn-phong"},
    {"NganHe", "he"}};

// conventions.channel_scale: factors of every colour value per channel (1, 1, 1 when absent).
std::array<double, 3> read_channel_scale(const nlohmann::json& doc, const std::string& where) {
  std::array<double, 3> out{1.0, 1.0, 1.0};
  if (!doc.contains("conventions") || !doc["conventions"].is_object() || !doc["conventions"].contains("channel_scale"))
    return out;
  const auto& x = doc["conventions"]["channel_scale"];
  if (!x.is_array() || x.size() != 3) throw InputError(where, "conventions.channel_scale is not 3 numbers");
  for (size_t c = 0; c < 3; ++c) {
    if (!x[c].is_number() || !(x[c].get<double>() > 0) || !std::isfinite(x[c].get<double>()))
      throw InputError(where, "conventions.channel_scale is not 3 positive numbers");
    out[c] = x[c].get<double>();
  }
  return out;
}

const Model* find_model(const std::string& name) {
  for (const Model* m : all_models())
    if (m->name() == name) return m;
  return nullptr;
}

// Per-channel value: an array of three numbers, or one number for all channels.
std::array<double, 3> channels(const nlohmann::json& params, const std::string& key, const std::string& where) {
  if (!params.contains(key)) throw InputError(where, "missing parameter '" + key + "'");
  const auto& x = params[key];
  std::array<double, 3> out{};
  if (x.is_number()) {
    out.fill(x.get<double>());
  } else if (x.is_array() && x.size() == 3 && std::all_of(x.begin(), x.end(), [](auto& e) { return e.is_number(); })) {
    for (int c = 0; c < 3; ++c) out[size_t(c)] = x[size_t(c)].get<double>();
  } else {
    throw InputError(where, "parameter '" + key + "' is neither a number nor an array of 3 numbers");
  }
  for (double v : out)
    if (!std::isfinite(v)) throw InputError(where, "parameter '" + key + "' is not finite");
  return out;
}

void put(ParamValues& v, const Model& m, const std::string& name, const std::array<double, 3>& x) {
  const int i = find_param(m.params(), name);
  if (i < 0) throw InputError("model '" + std::string(m.name()) + "'", "has no parameter '" + name + "'");
  for (int c = 0; c < 3; ++c) v.values[size_t(c)][size_t(i)] = x[size_t(c)];
}

std::array<double, 3> scaled(std::array<double, 3> x, double s) {
  for (double& v : x) v *= s;
  return x;
}
std::array<double, 3> scaled(std::array<double, 3> x, const std::array<double, 3>& s) {
  for (size_t c = 0; c < 3; ++c) x[c] *= s[c];
  return x;
}

// A lobe's "lobe" name; empty when absent. InputError naming `where` when it is not a string.
std::string lobe_name(const nlohmann::json& lobe, const std::string& where) {
  if (!lobe.contains("lobe")) return "";
  if (!lobe["lobe"].is_string()) throw InputError(where, "a lobe whose 'lobe' is not a string");
  return lobe["lobe"].get<std::string>();
}

// Published values may lie outside a model's fitting bounds (published_fits.h), but not where the
// model is undefined: there its evaluation throws (SGD's Γ(1 − p, α) needs p < 2) or gives NaN, and
// the error would name neither the file nor the parameter. So a BRDF with a value outside its
// bounds is evaluated at a few direction pairs away from the horizon, and refused, naming the first
// such value, unless every result is finite. Whatever the model throws there counts as undefined
// (its tables throw std::runtime_error when Λ cannot be tabulated).
void require_defined(const Brdf& brdf, const std::string& where) {
  const ParamTable& table = brdf.model().params();
  std::string outside;
  for (size_t i = 0; i < table.size() && outside.empty(); ++i)
    for (int c = 0; c < 3 && outside.empty(); ++c) {
      const double x = brdf.values().values[size_t(c)][i];
      if (!(x >= table[i].lower && x <= table[i].upper))
        outside = fmt::format("parameter '{}' = {} (channel {}) is outside the model's bounds [{}, {}]", table[i].name, x,
                              "RGB"[c], table[i].lower, table[i].upper);
    }
  if (outside.empty()) return;
  const std::pair<double, double> pairs[] = {{0.0, 0.0}, {0.5, 0.5}, {1.0, 0.3}, {1.2, 1.2}};  // (θi, θo), φo − φi = π
  for (const auto& [ti, to] : pairs) {
    std::string why;
    try {
      const Rgb v = brdf.eval(spherical_direction(ti, 0.0), spherical_direction(to, kPi));
      if (!v.allFinite()) why = fmt::format("the BRDF is not finite at θi = {}, θo = {} rad", ti, to);
    } catch (const std::exception& e) {
      why = e.what();
    }
    if (!why.empty()) throw InputError(where, outside + " and the model is not defined there: " + why);
  }
}

}  // namespace

const Model* bagher_sgd_model() {
  static const MicrofacetModelAdapter<BagherSgd> m;
  return &m;
}

const Model* low_cook_torrance_model() {
  static const MicrofacetModelAdapter<LowCookTorrance> m;
  return &m;
}

PublishedFits PublishedFits::read(const std::filesystem::path& file) {
  const std::string where = file.string();
  std::ifstream in(file);
  if (!in) throw InputError(where, "cannot open the file");
  if (file.extension() == ".fit") return from_document(read_bbm_fit_text(file), file);
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(where, std::string("not valid JSON: ") + e.what());
  }
  return from_document(std::move(doc), file);
}

PublishedFits PublishedFits::from_document(nlohmann::json doc, const std::filesystem::path& file) {
  const std::string where = file.string();
  PublishedFits out;
  out.file_ = file;
  if (!doc.is_object() || !doc.contains("materials") || !doc["materials"].is_object() || doc["materials"].empty())
    throw InputError(where, "no 'materials' object");
  out.materials_ = std::move(doc["materials"]);
  // The specular lobe's name: the first lobe that is not the Lambertian one.
  const auto& first = out.materials_.begin().value();
  if (!first.is_array()) throw InputError(where, "material '" + out.materials_.begin().key() + "' is not a list of lobes");
  const std::string first_where = where + ": material '" + out.materials_.begin().key() + "'";
  for (const auto& lobe : first)
    if (lobe.is_object())
      if (std::string name = lobe_name(lobe, first_where); name != "Lambertian") out.lobe_ = std::move(name);
  if (out.lobe_ == "LowSmooth") out.model_ = "low-smooth";
  else if (out.lobe_ == "LowAshikhminShirley") out.model_ = "ashikhmin-shirley-dielectric";
  else if (out.lobe_ == "LowCookTorrance") out.model_ = "cook-torrance-low2012";
  else if (out.lobe_ == "Bagher") out.model_ = "cook-torrance-sgd-bagher2012";
  else if (out.lobe_ == "LowMicrofacetFit") out.model_ = "low-microfacet";
  else if (const auto it = kNganModels.find(out.lobe_); it != kNganModels.end()) out.model_ = it->second;
  else {
    out.reason_ = "unknown lobe '" + out.lobe_ + "'";
  }
  out.channel_scale_ = read_channel_scale(doc, where);
  return out;
}

std::vector<std::string> PublishedFits::materials() const {
  std::vector<std::string> names;
  for (auto it = materials_.begin(); it != materials_.end(); ++it) names.push_back(it.key());
  std::sort(names.begin(), names.end());
  return names;
}

namespace {

// Ngan 2005's lobes (models/bbm_fit_text.cpp's conventions); `albedo(f)` is the file's albedo
// times f and the file's channel scale.
template <class Albedo>
bool put_ngan_lobe(ParamValues& v, const Model& m, const std::string& name, const nlohmann::json& p,
                   const std::string& lwhere, const Albedo& albedo) {
  const auto values = [&](const char* key) { return channels(p, key, lwhere); };
  if (name == "NganWard" || name == "NganWardDuer") {  // the same formulas as ward.h and ward_duer.h
    put(v, m, "ks", albedo(1.0));
    put(v, m, "alpha", values("roughness"));
  } else if (name == "NganLafortune") {  // lafortune.h's normalization, one lobe
    put(v, m, "ks", albedo(1.0));
    put(v, m, "Cxy", values("Cxy"));
    put(v, m, "Cz", values("Cz"));
    put(v, m, "N", values("sharpness"));
  } else if (name == "NganCookTorrance") {  // albedo·DGF/(π ci co) = (4 albedo/π) · DFG/(4 ci co)
    put(v, m, "ks", albedo(4.0 * kInvPi));
    put(v, m, "alpha", values("roughness"));
    put(v, m, "F0", values("eta"));
  } else if (name == "NganAshikhminShirley") {
    put(v, m, "ks", albedo(1.0));
    put(v, m, "N", values("sharpness"));
    put(v, m, "F0", values("fresnelReflectance"));
  } else if (name == "NganBlinnPhong") {  // albedo (n+2)/(2π) cosⁿθh = 4 albedo · (n+2)/(8π) cosⁿθh
    put(v, m, "ks", albedo(4.0));
    put(v, m, "N", values("sharpness"));
  } else if (name == "NganHe") {
    put(v, m, "ks", albedo(1.0));
    put(v, m, "sigma0", values("roughness"));
    put(v, m, "tau", values("autocorrelation"));
    put(v, m, "eta", values("eta"));
    put(v, m, "k", {0.0, 0.0, 0.0});
  } else {
    return false;
  }
  return true;
}

// The specular lobe `name` of a published file (parameters `p`) into the model's values, with the
// file's conventions (DESIGN.md §10). False for a lobe this converter does not know.
bool put_lobe(ParamValues& v, const Model& m, const std::string& name, const nlohmann::json& p, const std::string& lwhere,
              const std::array<double, 3>& colour) {
  const auto albedo = [&](double factor) { return scaled(scaled(channels(p, "albedo", lwhere), factor), colour); };
  if (name.starts_with("Ngan")) return put_ngan_lobe(v, m, name, p, lwhere, albedo);
  if (name == "LowSmooth") {
    for (const char* k : {"A", "B", "C", "eta"}) put(v, m, k, channels(p, k, lwhere));
  } else if (name == "LowAshikhminShirley") {
    put(v, m, "ks", channels(p, "albedo", lwhere));
    put(v, m, "N", channels(p, "sharpness", lwhere));
    put(v, m, "eta", channels(p, "fresnelReflectance", lwhere));
  } else if (name == "LowCookTorrance") {
    // albedo·D'·G·F/(π ci co) with D' = π D_Beckmann (no 1/π in the file's D) = 4·albedo · D F G/(4 ci co).
    put(v, m, "ks", scaled(channels(p, "albedo", lwhere), 4.0));
    put(v, m, "alpha", channels(p, "roughness", lwhere));
    put(v, m, "eta", channels(p, "eta", lwhere));
  } else if (name == "LowMicrofacetFit") {
    // conventions: A[c]·S·G·F/(π ci co); seed 003 Eq. 15 (the model) has no 1/π, so A = A[c]/π.
    put(v, m, "A", scaled(channels(p, "A", lwhere), kInvPi));
    for (const char* k : {"B", "C", "eta"}) put(v, m, k, channels(p, k, lwhere));
  } else if (name == "Bagher") {
    // albedo·D·G·F/(π ci co) (seed 000 Eq. 1, normalized D) = (4 albedo/π) · D F G/(4 ci co).
    put(v, m, "ks", scaled(channels(p, "albedo", lwhere), 4.0 * kInvPi));
    put(v, m, "alpha", channels(p, "alpha", lwhere));
    put(v, m, "p", channels(p, "p", lwhere));
    if (!p.contains("eta") || !p["eta"].is_array() || p["eta"].size() != 2)
      throw InputError(lwhere, "parameter 'eta' is not a pair [F0[3], F1[3]]");
    nlohmann::json f{{"F0", p["eta"][0]}, {"F1", p["eta"][1]}};
    put(v, m, "F0", channels(f, "F0", lwhere + " eta[0]"));
    put(v, m, "F1", channels(f, "F1", lwhere + " eta[1]"));
  } else {
    return false;
  }
  return true;
}

}  // namespace

Brdf PublishedFits::brdf(const std::string& material) const {
  const std::string where = file_.string();
  if (!supported()) throw InputError(where, "unsupported: " + reason_);
  if (!materials_.contains(material)) throw InputError(where, "no material '" + material + "'");
  const Model* m = model_ == "cook-torrance-low2012"          ? low_cook_torrance_model()
                   : model_ == "cook-torrance-sgd-bagher2012" ? bagher_sgd_model()
                                                              : find_model(model_);
  if (!m) throw InputError(where, "model '" + model_ + "' is not registered");
  ParamValues v = ParamValues::defaults(m->params());
  const std::string mwhere = where + ": material '" + material + "'";
  bool have_diffuse = false, have_lobe = false;
  for (const auto& lobe : materials_[material]) {
    if (!lobe.is_object() || !lobe.contains("params") || !lobe["params"].is_object())
      throw InputError(mwhere, "a lobe without a 'params' object");
    const std::string name = lobe_name(lobe, mwhere);
    const std::string lwhere = mwhere + ", lobe '" + name + "'";
    if (name == "Lambertian") {
      put(v, *m, "kd", scaled(channels(lobe["params"], "albedo", lwhere), channel_scale_));  // albedo[c]/π
      have_diffuse = true;
    } else if (name == lobe_ && put_lobe(v, *m, name, lobe["params"], lwhere, channel_scale_)) {
      have_lobe = true;
    } else {
      throw InputError(lwhere, "unexpected lobe in a '" + lobe_ + "' file");
    }
  }
  if (!have_diffuse) throw InputError(mwhere, "no 'Lambertian' lobe");
  if (!have_lobe) throw InputError(mwhere, "no '" + lobe_ + "' lobe");
  Brdf brdf(*m, std::move(v));
  require_defined(brdf, mwhere);
  return brdf;
}

std::vector<std::filesystem::path> published_fit_files(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> out;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec))
    if (e.is_regular_file() && (e.path().extension() == ".json" || e.path().extension() == ".fit"))
      out.push_back(e.path());
  if (ec) throw InputError(dir.string(), "cannot list the folder: " + ec.message());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace brdfkit
