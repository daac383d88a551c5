"""The plausible bugs of the mutation check (mutate.py).

Each mutant: id, family (what it breaks), bug (one line), edits [(file, exact old text, new
text)] (each old text must occur exactly once in its file), and quick: the tests most likely to
kill it, as (test executable target, gtest filter) pairs, run before the whole suite.
Every old text is a line (or a unique part of one) of the unmutated sources; when a source
changes so that an old text no longer matches, the mutant is reported as an error: update it.
"""

M = "brdfkit_models_tests"
REF = "brdfkit_models_reference_tests"
HE = "brdfkit_models_he_tests"
LOW = "brdfkit_models_low_tests"
HP = "brdfkit_models_holzschuch_pacanowski_tests"
RENDERER = "brdfkit_models_renderer_tests"
NDF = "brdfkit_ndf_tests"
MEASURED = "brdfkit_measured_tests"
METRIC = "brdfkit_fit_metric_tests"
PROCEDURE = "brdfkit_fit_procedure_tests"
CONVENTIONS = "brdfkit_conventions_tests"
CLI = "brdfkit_cli_tests"
EXPORT = "brdfkit_export_tests"

MUTANTS = [
    # --- models ---------------------------------------------------------------------------
    {
        "id": "lambert-constant",
        "family": "model/lambert",
        "bug": "Lambert kd/pi 10 % low (0.9/pi)",
        "edits": [("src/brdfkit/models/lambert.h", "    return p[0] * T(kInvPi);", "    return p[0] * T(0.9 * kInvPi);")],
        "quick": [(REF, "LambertReference.*")],
    },
    {
        "id": "ward-norm",
        "family": "model/ward",
        "bug": "Ward normalization 4pi -> 4.4pi",
        "edits": [("src/brdfkit/models/ward.h", "(T(4 * kPi) * a * a * sqrt(wi.z() * wo.z()))",
                   "(T(4.4 * kPi) * a * a * sqrt(wi.z() * wo.z()))")],
        "quick": [(REF, "WardReference.*")],
    },
    {
        "id": "ward-pdf-wide",
        "family": "model/ward sampling",
        "bug": "Ward sampling pdf 5 % too wide (alpha * 1.05), still normalized",
        "edits": [("src/brdfkit/models/ward.h",
                   "return std::exp(-exponent<double>(h, ax, ay)) / (kPi * ax * ay * c3);",
                   "return std::exp(-exponent<double>(h, 1.05 * ax, 1.05 * ay)) / (kPi * 1.05 * ax * 1.05 * ay * c3);")],
        "quick": [(M, "EveryModel/Chi2Power.*/ward")],
    },
    {
        "id": "ward-duer-cosine",
        "family": "model/ward-duer",
        "bug": "Ward-Duer denominator drops cos(theta_i)",
        "edits": [("src/brdfkit/models/ward_duer.h", "(T(4 * kPi) * a * a * wi.z() * wo.z())", "(T(4 * kPi) * a * a * wo.z())")],
        "quick": [(REF, "WardReference.WardDuer*")],
    },
    {
        "id": "blinn-phong-constant",
        "family": "model/blinn-phong",
        "bug": "Blinn-Phong normalization (N+2)/(8pi) -> (N+1)/(8pi)",
        "edits": [("src/brdfkit/models/blinn_phong_lobe.h", "p[1] * (p[2] + T(2)) / T(8 * kPi)", "p[1] * (p[2] + T(1)) / T(8 * kPi)")],
        "quick": [(REF, "PhongFamilyReference.BlinnPhong*")],
    },
    {
        "id": "lafortune-swapped-coefficients",
        "family": "model/lafortune",
        "bug": "Lafortune Cxy and Cz swapped in the lobe's dot product",
        "edits": [("src/brdfkit/models/lafortune.h",
                   "const T dot = q[1] * (wi.x() * wo.x() + wi.y() * wo.y()) + q[2] * wi.z() * wo.z();",
                   "const T dot = q[2] * (wi.x() * wo.x() + wi.y() * wo.y()) + q[1] * wi.z() * wo.z();")],
        "quick": [(REF, "PhongFamilyReference.Lafortune*")],
    },
    {
        "id": "ashikhmin-shirley-min",
        "family": "model/ashikhmin-shirley",
        "bug": "Ashikhmin-Shirley max(cos_i, cos_o) written as min",
        "edits": [("src/brdfkit/models/ashikhmin_shirley.h", "const T mx = wi.z() > wo.z() ? wi.z() : wo.z();",
                   "const T mx = wi.z() < wo.z() ? wi.z() : wo.z();")],
        "quick": [(REF, "PhongFamilyReference.AshikhminShirley*")],
    },
    {
        "id": "cook-torrance-cosine",
        "family": "model/cook-torrance",
        "bug": "Cook-Torrance eval drops cos(theta_o) from 4 cos_i cos_o",
        "edits": [("src/brdfkit/models/cook_torrance.h", "masking(ndf, wiz, woz, ch, cd) / (T(4) * wiz * woz);",
                   "masking(ndf, wiz, woz, ch, cd) / (T(4) * wiz);")],
        "quick": [(REF, "CookTorranceReference.*"), (M, "CookTorrance.*")],
    },
    {
        "id": "ggx-alpha-power",
        "family": "ndf/ggx",
        "bug": "GGX D with alpha instead of alpha^2 in the numerator",
        "edits": [("src/brdfkit/ndf/ggx.h", "const T s = denom(a2, cos_theta);\n    return a2 / (T(kPi) * s * s);",
                   "const T s = denom(a2, cos_theta);\n    return alpha / (T(kPi) * s * s);")],
        "quick": [(NDF, "NdfNormalization.Ggx*"), (REF, "CookTorranceReference.*")],
    },
    {
        "id": "beckmann-sample-alpha",
        "family": "ndf/beckmann sampling",
        "bug": "Beckmann sampling tan^2 = -alpha ln(1-u) (alpha not squared)",
        "edits": [("src/brdfkit/ndf/beckmann.h", "const double tan2 = -a * a * std::log1p(-u.x());",
                   "const double tan2 = -a * std::log1p(-u.x());")],
        "quick": [(NDF, "NdfSampling.Beckmann"), (M, "EveryModel/Chi2Power.*/cook_torrance_beckmann")],
    },
    {
        "id": "he-constant",
        "family": "model/he",
        "bug": "He distribution constant pi^2/(4 lambda^2) -> pi^2/(4.4 lambda^2)",
        "edits": [("src/brdfkit/models/he_torrance.h", "T(kPi * kPi / (4 * lambda * lambda))",
                   "T(kPi * kPi / (4.4 * lambda * lambda))")],
        "quick": [(REF, "HeReference.*"), (HE, "HeReference.*")],
    },
    {
        "id": "low-smooth-swapped-bc",
        "family": "model/low-smooth",
        "bug": "Low smooth-surface ABC called with B and C swapped",
        "edits": [("src/brdfkit/models/low_smooth.h", "low_smooth_detail::abc(p[1], p[2], p[3], dp2);",
                   "low_smooth_detail::abc(p[1], p[3], p[2], dp2);")],
        "quick": [(REF, "LowReference.SmoothSurface"), (LOW, "LowSmooth.*")],
    },
    {
        "id": "low-microfacet-cosine",
        "family": "model/low-microfacet",
        "bug": "Low ABC microfacet drops cos(theta_i) from cos_i cos_o",
        "edits": [("src/brdfkit/models/low_microfacet.h", "v_groove_g(wi, wo) /\n                   (wi.z() * wo.z());",
                   "v_groove_g(wi, wo) /\n                   (wo.z());")],
        "quick": [(REF, "LowReference.AbcMicrofacet"), (LOW, "LowMicrofacet.*")],
    },
    {
        "id": "hp-lambda-cubed",
        "family": "model/holzschuch-pacanowski",
        "bug": "Holzschuch-Pacanowski diffraction over lambda^3 instead of lambda^4",
        "edits": [("src/brdfkit/models/holzschuch_pacanowski.h", "const T lambda4 = T(lambda * lambda * lambda * lambda);",
                   "const T lambda4 = T(lambda * lambda * lambda);")],
        "quick": [(REF, "HolzschuchPacanowskiReference.*"), (HP, "*")],
    },
    {
        "id": "gltf-visibility-swapped",
        "family": "model/gltf (renderer)",
        "bug": "glTF visibility term with n.l and n.v swapped",
        "edits": [("src/brdfkit/models/gltf_metallic_roughness.h",
                   "T(0.5) / (nv * sqrt(a2 + (T(1) - a2) * nl * nl) + nl * sqrt(a2 + (T(1) - a2) * nv * nv));",
                   "T(0.5) / (nl * sqrt(a2 + (T(1) - a2) * nl * nl) + nv * sqrt(a2 + (T(1) - a2) * nv * nv));")],
        "quick": [(REF, "RendererModelsReference.Gltf*"), (RENDERER, "RendererReference.Gltf")],
    },
    {
        "id": "gltf-ior-default",
        "family": "model/gltf default",
        "bug": "glTF ior default 1.5 -> 1.4 (KHR_materials_ior's default is 1.5)",
        "edits": [("src/brdfkit/models/gltf_metallic_roughness.h", '{"ior", 1.0, 5.0, 1.5, Scope::Shared',
                   '{"ior", 1.0, 5.0, 1.4, Scope::Shared')],
        "quick": [(EXPORT, "ExportFiles.GltfWithoutExtensionsReadsWithTheirDefaults")],
    },
    {
        "id": "disney-fd90",
        "family": "model/disney (renderer)",
        "bug": "Disney diffuse Fd90 = 0.5 + 2 roughness cos_d (cos_d not squared)",
        "edits": [("src/brdfkit/models/disney_principled.h", "const T fd90 = T(0.5) + T(2) * lh * lh * p[kRoughness];",
                   "const T fd90 = T(0.5) + T(2) * lh * p[kRoughness];")],
        "quick": [(REF, "RendererModelsReference.DisneyPrincipled"), (RENDERER, "RendererReference.Disney")],
    },
    {
        "id": "pbrt-roughness-remap",
        "family": "model/pbrt (renderer)",
        "bug": "pbrt conductor without RoughnessToAlpha (alpha = roughness, not sqrt)",
        "edits": [("src/brdfkit/models/pbrt_conductor.h", "  const T alpha = sqrt(roughness);", "  const T alpha = roughness;")],
        "quick": [(REF, "RendererModelsReference.Pbrt*"), (RENDERER, "RendererReference.Pbrt*")],
    },
    # --- readers ---------------------------------------------------------------------------
    {
        "id": "merl-blue-scale",
        "family": "reader/merl",
        "bug": "MERL blue scale 1.66/1500 -> 1.5/1500",
        "edits": [("src/brdfkit/measured/merl.h", "1.66 / 1500.0}", "1.5 / 1500.0}")],
        "quick": [(MEASURED, "MerlFile.HandWrittenFileReadsWithTheReferenceChannelScales")],
    },
    {
        "id": "merl-theta-d-off-by-one",
        "family": "reader/merl",
        "bug": "MERL theta_d cell index one cell too high",
        "edits": [("src/brdfkit/measured/merl.cpp", "const double t = theta_d / (kPi * 0.5) * kResThetaD;",
                   "const double t = theta_d / (kPi * 0.5) * kResThetaD + 1;")],
        "quick": [(MEASURED, "Merl*")],
    },
    {
        "id": "merl-phi-d-mirror",
        "family": "reader/merl",
        "bug": "MERL phi_d < 0 mirrored (-phi_d) instead of shifted by pi",
        "edits": [("src/brdfkit/measured/merl.cpp", "  if (phi_d < 0.0) phi_d += kPi;", "  if (phi_d < 0.0) phi_d = -phi_d;")],
        "quick": [(MEASURED, "Merl*")],
    },
    {
        "id": "rgl-sigma",
        "family": "reader/rgl",
        "bug": "every RGL value 9 % low (sigma scaled by 1.1 in the reader)",
        "edits": [("src/brdfkit/measured/rgl_tensor.cpp", "ndf.eval(u_m) / (4 * c.sigma * cos_theta)",
                   "ndf.eval(u_m) / (4 * 1.1 * c.sigma * cos_theta)"),
                  ("src/brdfkit/measured/rgl_tensor.cpp", "v *= ndf_.eval(u_m) / (4 * sigma_c * wx.z());",
                   "v *= ndf_.eval(u_m) / (4 * 1.1 * sigma_c * wx.z());")],
        "quick": [(MEASURED, "Rgl*")],
    },
    {
        "id": "rgl-angles-swapped",
        "family": "reader/rgl",
        "bug": "RGL conditioning angles (phi, theta) passed as (theta, phi)",
        "edits": [("src/brdfkit/measured/rgl_tensor.cpp", "  c.params[0] = phi_c;\n  c.params[1] = theta_c;",
                   "  c.params[0] = theta_c;\n  c.params[1] = phi_c;")],
        "quick": [(MEASURED, "Rgl*")],
    },
    {
        "id": "cornell-ring-edges",
        "family": "reader/cornell",
        "bug": "Cornell ring band edges at k/10 instead of (k - 1/2)/10",
        "edits": [("src/brdfkit/measured/cornell.cpp", "std::pow((k - 0.5) / 10, 2)", "std::pow(k / 10.0, 2)")],
        "quick": [(MEASURED, "Cornell*")],
    },
    {
        "id": "alta-interpolation-swapped",
        "family": "reader/alta",
        "bug": "ALTA slice interpolation weights swapped",
        "edits": [("src/brdfkit/measured/alta_slice.cpp", "return Rgb((1 - t) * rgb_[lo] + t * rgb_[hi]);",
                   "return Rgb(t * rgb_[lo] + (1 - t) * rgb_[hi]);")],
        "quick": [(MEASURED, "AltaSlice.*"), (METRIC, "ScatteredMetric.AltaSlice*")],
    },
    {
        "id": "alta-solid-angle",
        "family": "reader/alta",
        "bug": "ALTA row solid angle pi dcos instead of 2 pi dcos",
        "edits": [("src/brdfkit/measured/alta_slice.cpp", "s.push_back(w, w, rgb_[k], 2 * kPi * (hi - lo), cos_th_[k] > 0);",
                   "s.push_back(w, w, rgb_[k], kPi * (hi - lo), cos_th_[k] > 0);")],
        "quick": [(MEASURED, "AltaSlice.*"), (METRIC, "ScatteredMetric.AltaSlice*")],
    },
    # --- metrics ---------------------------------------------------------------------------
    {
        "id": "ngan-weight-cos",
        "family": "metric/ngan",
        "bug": "ngan weight cos(theta) instead of sin(theta)",
        "edits": [("src/brdfkit/fit/metric/ngan_metric.cpp", "for (AxisNode& n : *axis) n.weight = std::sin(n.angle);",
                   "for (AxisNode& n : *axis) n.weight = std::cos(n.angle);")],
        "quick": [(METRIC, "*Ngan*"), (CONVENTIONS, "MetricConvention.Ngan*")],
    },
    {
        "id": "low-e2-transform",
        "family": "metric/low",
        "bug": "low-e1 and low-e2 transforms swapped",
        "edits": [("src/brdfkit/fit/metric/low_metric.cpp", "d.transform = m == 2 ? Transform::Log1p : Transform::Identity;",
                   "d.transform = m == 1 ? Transform::Log1p : Transform::Identity;")],
        "quick": [(METRIC, "*Low*"), (CONVENTIONS, "MetricConvention.Low*")],
    },
    {
        "id": "bagher-metric-cosine",
        "family": "metric/bagher",
        "bug": "bagher metric drops cos(theta_o) from its weight",
        "edits": [("src/brdfkit/fit/metric/bagher_metric.cpp",
                   "for (AxisNode& n : d.grid.theta_o) n.weight *= std::sin(n.angle) * std::cos(n.angle);",
                   "for (AxisNode& n : d.grid.theta_o) n.weight *= std::sin(n.angle);")],
        "quick": [(METRIC, "*Bagher*"), (CONVENTIONS, "MetricConvention.Bagher*")],
    },
    {
        "id": "hp-rmse-limit",
        "family": "metric/hp-rmse",
        "bug": "hp-rmse grid up to 1.5 rad instead of 1.4",
        "edits": [("src/brdfkit/fit/metric/hp_metric.cpp", "const double limit = 1.4 - 1e-12;", "const double limit = 1.5 - 1e-12;")],
        "quick": [(METRIC, "*HpRmse*"), (CONVENTIONS, "MetricConvention.HpRmse*")],
    },
    {
        "id": "max-albedo-cosine",
        "family": "metric/albedo normalization",
        "bug": "max measured albedo drops cos(theta_o) (integrates rho dw, not rho cos dw)",
        "edits": [("src/brdfkit/fit/metric/metric.cpp", "w.push_back(ct * st * o.weight * p.weight);",
                   "w.push_back(st * o.weight * p.weight);")],
        "quick": [(METRIC, "Metric.*"), (CONVENTIONS, "MetricConvention.*")],
    },
    {
        "id": "metric-cells-theta-h-off-by-one",
        "family": "metric/merl cells",
        "bug": "MERL cell measure with theta_h edges one cell off",
        "edits": [("src/brdfkit/fit/metric/metric_cells.cpp", "const double u = double(i) / kResThetaH;",
                   "const double u = double(i + 1) / kResThetaH;")],
        "quick": [(METRIC, "MetricCells.*")],
    },
    # --- procedures -------------------------------------------------------------------------
    {
        "id": "bagher-fresnel-ks",
        "family": "procedure/bagher",
        "bug": "bagher procedure ks = ks F0 (drops ks (1 - F0) of F(pi/2) = 1)",
        "edits": [("src/brdfkit/fit/procedure/bagher_procedure.cpp", "const double ks = abe[0] + abe[1];  // F(π/2) = 1",
                   "const double ks = abe[0];  // F(π/2) = 1")],
        "quick": [(PROCEDURE, "BagherProcedure.*:BagherRecovery.*")],
    },
    {
        "id": "hp-step1-reflection-on",
        "family": "procedure/hp-2step",
        "bug": "hp-2step leaves the reflection lobe on in step 1",
        "edits": [("src/brdfkit/fit/procedure/hp_procedure.cpp", "  for (auto& ch : start.values) ch[size_t(ks)] = 0.0;\n", "")],
        "quick": [(PROCEDURE, "HpProcedure.*:HpTwoStep.*")],
    },
    {
        "id": "low-e2-procedure-metric",
        "family": "procedure/low-e2",
        "bug": "the low-e2 procedure fits under low-e1",
        "edits": [("src/brdfkit/fit/procedure/procedure.cpp", "(seed 003 §5.1)\", &single_fit<kLowE2>}",
                   "(seed 003 §5.1)\", &single_fit<kLowE1>}")],
        "quick": [(PROCEDURE, "Procedures.*")],
    },
    {
        "id": "fixed-params-merged-index",
        "family": "procedure/fixed params",
        "bug": "FixedParams::merged writes free value k to parameter k, not to its own index",
        "edits": [("src/brdfkit/fit/procedure/fixed_params.cpp",
                   "out.values[size_t(c)][size_t(free_[k])] = free_values.values[size_t(c)][k];",
                   "out.values[size_t(c)][k] = free_values.values[size_t(c)][k];")],
        "quick": [(PROCEDURE, "FixedParams.*:HpProcedure.*")],
    },
    {
        "id": "hp-threshold-default",
        "family": "procedure/settings default",
        "bug": "hp-2step threshold default 1e-2 -> 1e-3 (seed 004 section 4.2 uses 1e-2)",
        "edits": [("src/brdfkit/fit/settings/fit_settings.h", "  double threshold = 1e-2;", "  double threshold = 1e-3;")],
        "quick": [(PROCEDURE, "HpProcedure.*:HpTwoStep.*")],
    },
    # --- command line ---------------------------------------------------------------------------
    {
        "id": "eval-swapped",
        "family": "cli/eval",
        "bug": "brdfkit eval evaluates rho(wo, wi)",
        "edits": [("apps/brdfkit/cmd_eval.cpp", "eval_measured(a.brdf.model, wi, wo, out) : eval_model(a.brdf, wi, wo, out)",
                   "eval_measured(a.brdf.model, wo, wi, out) : eval_model(a.brdf, wo, wi, out)")],
        "quick": [(CONVENTIONS, "EvalCliConvention.*"), (CLI, "EvalCli.*")],
    },
]
