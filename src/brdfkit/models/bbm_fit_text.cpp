#include "brdfkit/models/bbm_fit_text.h"

#include <cctype>
#include <fstream>
#include <map>
#include <string_view>

#include "brdfkit/core/error.h"
#include "brdfkit/core/text.h"

namespace brdfkit {

namespace {

// A recursive-descent reader of one line's `Lobe(key = value, ...)` calls.
class LineReader {
 public:
  LineReader(std::string_view text, std::string where) : s_(text), where_(std::move(where)) {}

  std::string identifier() {
    skip_space();
    const size_t start = i_;
    while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_' || s_[i_] == '-')) ++i_;
    if (i_ == start) fail("a name");
    return std::string(s_.substr(start, i_ - start));
  }
  void expect(char c) {
    skip_space();
    if (i_ >= s_.size() || s_[i_] != c) fail(std::string("'") + c + "'");
    ++i_;
  }
  bool accept(char c) {
    skip_space();
    if (i_ < s_.size() && s_[i_] == c) return ++i_, true;
    return false;
  }
  bool at_end() {
    skip_space();
    return i_ == s_.size();
  }
  // A number, or a bracketed list of numbers.
  nlohmann::json value() {
    if (!accept('[')) return number();
    nlohmann::json list = nlohmann::json::array();
    do list.push_back(number());
    while (accept(','));
    expect(']');
    return list;
  }
  // Name(key = value, ...) → {"lobe": Name, "params": {...}}; an Aggregate's arguments are calls.
  nlohmann::json call() {
    nlohmann::json out{{"lobe", identifier()}, {"params", nlohmann::json::object()}};
    expect('(');
    if (accept(')')) return out;
    do {
      const std::string key = identifier();
      expect('=');
      if (out["params"].contains(key)) fail("one value for '" + key + "'");
      out["params"][key] = value();
    } while (accept(','));
    expect(')');
    return out;
  }
  [[noreturn]] void fail(const std::string& wanted) const {
    throw InputError(where_, "expected " + wanted + " at column " + std::to_string(i_ + 1));
  }

 private:
  nlohmann::json number() {
    skip_space();
    const size_t start = i_;
    while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '.' || s_[i_] == '-' ||
                              s_[i_] == '+'))
      ++i_;
    const std::optional<double> x = finite_number(std::string(s_.substr(start, i_ - start)));
    if (!x) {
      i_ = start;
      fail("a finite number");
    }
    return *x;
  }
  void skip_space() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  std::string_view s_;
  size_t i_ = 0;
  std::string where_;
};

}  // namespace

nlohmann::json read_bbm_fit_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string(), "cannot open the file");
  nlohmann::json doc{{"materials", nlohmann::json::object()}};
  std::string line, specular, source;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string where = file.string() + ":" + std::to_string(number);
    if (line.starts_with("#")) {  // the header: where the fits come from
      const size_t text = line.find_first_not_of("# ");
      if (text == std::string::npos) continue;
      if (!source.empty()) source += ' ';
      source.append(line, text);
      continue;
    }
    LineReader r(line, where);
    if (r.at_end()) continue;
    const std::string name = r.identifier();
    r.expect('=');
    nlohmann::json list = nlohmann::json::array();
    if (r.identifier() != "Aggregate") r.fail("Aggregate(...)");
    r.expect('(');
    do list.push_back(r.call());
    while (r.accept(','));
    r.expect(')');
    if (!r.at_end()) r.fail("the end of the line");
    if (doc["materials"].contains(name)) throw InputError(where, "material '" + name + "' appears twice");
    for (const auto& lobe : list)
      if (lobe["lobe"] != "Lambertian") specular = lobe["lobe"].get<std::string>();
    doc["materials"][name] = std::move(list);
  }
  if (doc["materials"].empty()) throw InputError(file.string(), "no material line");
  doc["source"] = source;
  doc["conventions"] = ngan2005_conventions(specular);
  return doc;
}

// What each lobe's values mean (published-fits/ngan2005/README.md, as BBM evaluates them), and
// MERL's per-channel factors: Ngan's colours fit MERL values read without them (DESIGN.md §2:
// 1, 1.15, 1.66 for R, G, B), so brdfkit multiplies every colour by them
// (tests/models/test_ngan_published_fits.cpp measures the ratio against Bagher's fits).
nlohmann::json ngan2005_conventions(const std::string& lobe) {
  static const std::map<std::string, std::string> formulas = {
      {"NganWard", "albedo[c] exp(-tan(theta_h)^2 / roughness^2) / (4 pi roughness^2 sqrt(cos_i cos_o))"},
      {"NganWardDuer", "albedo[c] exp(-tan(theta_h)^2 / roughness^2) / (4 pi roughness^2 cos_i cos_o)"},
      {"NganLafortune",
       "albedo[c] (n+2)/(2 pi) max(0, Cxy (ux vx + uy vy) + Cz uz vz)^n / max(|Cxy|, |Cz|)^n, n = sharpness"},
      {"NganCookTorrance",
       "albedo[c] D G F / (pi cos_i cos_o): Beckmann D with its 1/pi (m = roughness), V-groove G, Schlick F with "
       "F0 = the field 'eta'"},
      {"NganAshikhminShirley",
       "albedo[c] Schlick(F0; wi.h) (n+1)/(8 pi) cos(theta_h)^n / ((wi.h) max(cos_i, cos_o)), F0 = "
       "fresnelReflectance, n = sharpness"},
      {"NganBlinnPhong", "albedo[c] (n+2)/(2 pi) cos(theta_h)^n, n = sharpness (half vector)"},
      {"NganHe",
       "albedo[c] x He 1991's directional-diffuse term, sigma0 = roughness and tau = autocorrelation in um, real "
       "index eta, wavelengths 0.645 / 0.526 / 0.444 um"}};
  const auto it = formulas.find(lobe);
  if (it == formulas.end()) return nlohmann::json::object();
  return {{"paper", "Ngan, Durand & Matusik 2005 (seed 002), fits to the MERL materials as collected by BBM"},
          {"formula", "rho = Lambertian + " + lobe},
          {"Lambertian", "albedo[c] / pi"},
          {lobe, it->second},
          {"channel_scale", {1.0, 1.15, 1.66}}};
}

}  // namespace brdfkit
