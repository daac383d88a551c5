#pragma once
// Named sets of catalogue models for batch fitting (`fit-all --models`), read from the model
// table itself so a model added to the registry joins the sets without another list to edit.
//
// Lobe count, from the parameter table: a specular lobe is announced by its per-channel linear
// scale (ks, A, ks1, kw …); the Lambertian `kd` is the diffuse term, not a lobe. A model whose
// only lobe has no linear scale (Ashikhmin-Shirley: its Rs is the Fresnel F0) but which has a
// shared shape parameter counts one lobe. So lambert has 0, cook-torrance-* 1, lafortune-2 and
// low-smooth-2 2, Holzschuch-Pacanowski 2 (reflection + diffraction).
#include <string>
#include <vector>

#include "brdfkit/models/model.h"

namespace brdfkit {

int lobe_count(const Model& model);

// Whether the model is a renderer's own BSDF (glTF, Mitsuba 3, pbrt-v4, Disney BRDF Explorer: the
// `gltf-`, `mitsuba-`, `pbrt-` and `disney-` models). Those form the set "renderer" and are not
// in "single-lobe", whose members share brdfkit's kd + lobe parameterization.
bool is_renderer_model(const Model& model);

// Whether the model turns its lobe by a fitted tangent angle (a parameter phi_t): on isotropic data
// the angle is undetermined, so these form the set "anisotropic" (with ward-aniso, whose tangent is
// the frame's) and are not in "single-lobe".
bool is_oriented(const Model& model);

// "all" (every catalogue model), "single-lobe" (lobe_count == 1, renderer and oriented models
// excluded), "renderer" (is_renderer_model), "anisotropic" (is_oriented, and ward-aniso) or a comma-separated list of
// model names; registry order for the sets, the given order for a list (duplicates dropped).
// InputError for an unknown name or an empty list.
std::vector<const Model*> parse_model_set(const std::string& spec);

}  // namespace brdfkit
