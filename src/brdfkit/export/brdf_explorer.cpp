#include "brdfkit/export/brdf_explorer.h"

#include <fmt/format.h>

#include "brdfkit/core/atomic_file.h"
#include "brdfkit/core/error.h"
#include "brdfkit/export/glsl_function.h"
#include "brdfkit/fit/fit_record.h"

namespace brdfkit::exporter {

std::string brdf_explorer_text(const Brdf& brdf, const Provenance& p) {
  const ParamTable& t = brdf.model().params();
  const auto& v = brdf.values().values;
  if (fit::shape_differs_by_channel(brdf.model(), brdf.values()))
    throw InputError("BRDF Explorer export", "a fit with a per-channel shape has one value per shared parameter there");
  std::string params, defines;
  for (size_t i = 0; i < t.size(); ++i) {
    const std::string n = glsl_name(t[i].name);
    if (t[i].scope == Scope::Shared) {
      params += fmt::format("float {} {} {} {}\n", n, glsl_float(t[i].lower), glsl_float(t[i].upper), glsl_float(v[0][i]));
    } else if (t[i].lower >= 0 && t[i].upper <= 1) {
      params += fmt::format("color {} {} {} {}\n", n, glsl_float(v[0][i]), glsl_float(v[1][i]), glsl_float(v[2][i]));
    } else {
      for (int c = 0; c < 3; ++c)
        params += fmt::format("float {}_{} {} {} {}\n", n, "rgb"[c], glsl_float(t[i].lower), glsl_float(t[i].upper),
                              glsl_float(v[size_t(c)][i]));
      defines += fmt::format("#define {0} vec3({0}_r, {0}_g, {0}_b)\n", n);
    }
  }
  std::string out = "analytic\n\n";
  for (const std::string& line : provenance_lines(p)) out += "# " + line + "\n";
  out += "\n::begin parameters\n" + params + "::end parameters\n\n::begin shader\n" + defines +
         glsl_functions(brdf.model()) +
         "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return brdfkit_brdf(L, V, N, X, Y); }\n::end shader\n";
  return out;
}

void write_brdf_explorer(const std::filesystem::path& file, const Brdf& brdf, const Provenance& p) {
  write_file_atomically(file, brdf_explorer_text(brdf, p));
}

}  // namespace brdfkit::exporter
