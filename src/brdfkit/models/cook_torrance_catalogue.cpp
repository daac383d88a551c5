// Runtime instances of the Cook-Torrance catalogue (one translation unit for all instantiations).
#include "brdfkit/models/cook_torrance_catalogue.h"

#include "brdfkit/models/cook_torrance_models.h"
#include "brdfkit/models/microfacet_model.h"

namespace brdfkit {

namespace {
template <class M> const Model* microfacet_instance() {
  static const MicrofacetModelAdapter<M> m;
  return &m;
}
}  // namespace

const std::vector<const Model*>& cook_torrance_models() {
  static const std::vector<const Model*> models = [] {
    std::vector<const Model*> out = {microfacet_instance<CookTorranceNgan>()};
    Distributions::for_each([&]<template <class> class D>() { out.push_back(microfacet_instance<CookTorranceWith<D>>()); });
    return out;
  }();
  return models;
}

}  // namespace brdfkit
