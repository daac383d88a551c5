#pragma once
// Gives a model template instantiation its catalogue name and description, so one template
// (e.g. CookTorrance<Ndf, Fresnel>) serves many registered models without a name per type.
#include <algorithm>
#include <cstddef>
#include <string_view>

namespace brdfkit {

// A string literal usable as a template argument (C++20 class-type non-type parameter).
template <std::size_t N> struct FixedString {
  char chars[N]{};
  constexpr FixedString(const char (&s)[N]) { std::copy_n(s, N, chars); }
  constexpr std::string_view view() const { return {chars, N - 1}; }
};

template <class M, FixedString Name, FixedString Description> struct Named : M {
  static std::string_view name() { return Name.view(); }
  static std::string_view description() { return Description.view(); }
};

}  // namespace brdfkit
