#pragma once
// Every normalized microfacet distribution of brdfkit, once. The Cook-Torrance models of the
// catalogue (models/cook_torrance_catalogue.h), the back-scatter families (analysis/backscatter.h),
// the conversions of `convert-ndf` (analysis/ndf_conversion.h, for those with a kUnitForm) and the
// typed conformance tests (normalization, χ² sampling, Jets, Smith tables) are generated from this
// list: a new distribution is its header (ndf/distribution.h says what it provides) plus its
// #include and its entry here. The order is the order of `brdfkit models`.
#include <cstddef>

#include "brdfkit/ndf/beckmann.h"
#include "brdfkit/ndf/blinn_phong.h"
#include "brdfkit/ndf/distribution.h"
#include "brdfkit/ndf/exponential.h"
#include "brdfkit/ndf/exponential_power.h"
#include "brdfkit/ndf/gaussian.h"
#include "brdfkit/ndf/ggx.h"
#include "brdfkit/ndf/gtr.h"
#include "brdfkit/ndf/sawicki_rational.h"
#include "brdfkit/ndf/schlick_rational.h"
#include "brdfkit/ndf/sgd.h"

namespace brdfkit {

template <template <class> class... Ds>
  requires(Distribution<Ds> && ...)
struct DistributionList {
  static constexpr std::size_t size = sizeof...(Ds);
  // f.template operator()<D>() for every D, in order: for_each([]<template <class> class D>() {…}).
  template <class F> static void for_each(F&& f) { (f.template operator()<Ds>(), ...); }
  // Meta<Ds...>: the list's distributions as another template's arguments.
  template <template <template <class> class...> class Meta> using apply = Meta<Ds...>;
};

using Distributions = DistributionList<Beckmann, BlinnPhong, Gaussian, Ggx, Gtr, Exponential, Sgd, ExponentialPower,
                                       SchlickRational, SawickiRational>;

}  // namespace brdfkit
