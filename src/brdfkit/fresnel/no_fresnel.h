#pragma once
// F = 1, for models that omit the Fresnel factor (DESIGN.md §5); no parameters.
#include "brdfkit/core/param.h"

namespace brdfkit {

template <class T> struct NoFresnel {
  static ParamTable params() { return {}; }
  explicit NoFresnel(const T* = nullptr) {}
  T eval(const T&) const { return T(1); }
};

}  // namespace brdfkit
