#pragma once
// GLSL for a fitted model: `vec3 brdfkit_brdf(vec3 wi, vec3 wo)` returns ρ(wi, wo) per RGB channel
// in sr⁻¹ (no cosine), wi towards the light and wo towards the viewer in the local frame (n = +z,
// DESIGN.md §2), and `vec3 brdfkit_brdf(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)` the same in any
// frame (BRDF Explorer's signature). The fitted values are `const` declarations at the top
// (per-channel parameters vec3, shared ones float), or, for BRDF Explorer, names its parameter
// block declares. Each model's GLSL transcribes the same formula as its C++ (cited there); float
// precision. Not every model has a GLSL form yet: glsl_models() lists those that do.
#include <string>
#include <vector>

#include "brdfkit/export/provenance.h"
#include "brdfkit/models/model.h"

namespace brdfkit::exporter {

// The models with a GLSL transcription.
std::vector<std::string> glsl_models();

// A GLSL identifier for a parameter name ("1.ks" → "p1_ks").
std::string glsl_name(const std::string& param);

// The functions (helpers and both brdfkit_brdf overloads), reading the parameters by glsl_name;
// InputError naming the model when it has no GLSL form.
std::string glsl_functions(const Model& model);
// `const` declarations of the fitted values (float literals, 9 significant digits).
std::string glsl_constants(const Brdf& brdf);
// A self-contained GLSL file: provenance comment, constants, functions (no #version line, so it
// can be included in any shader of GLSL 1.30 or later).
std::string glsl_file(const Brdf& brdf, const Provenance& p);

// A float literal GLSL accepts ("1.0", "2.5e-05").
std::string glsl_float(double x);

}  // namespace brdfkit::exporter
