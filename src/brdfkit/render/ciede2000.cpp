#include "brdfkit/render/ciede2000.h"

#include <cmath>

namespace brdfkit::render {
namespace {

constexpr double kDeg = kPi / 180;

// Sharma et al. 2005 Eqs. 2–7: C′ and h′ (degrees in [0, 360), 0 for a neutral colour).
struct PrimedChroma {
  double c, h;
};
PrimedChroma primed(const Lab& x, double g) {
  const double a = (1 + g) * x.a;
  const double c = std::hypot(a, x.b);
  double h = (a == 0 && x.b == 0) ? 0 : std::atan2(x.b, a) / kDeg;
  if (h < 0) h += 360;
  return {c, h};
}

}  // namespace

double ciede2000(const Lab& x, const Lab& y) {
  // Step 1 (Eqs. 2–7).
  const double cbar = (std::hypot(x.a, x.b) + std::hypot(y.a, y.b)) / 2;
  const double cbar7 = std::pow(cbar, 7);
  const double g = 0.5 * (1 - std::sqrt(cbar7 / (cbar7 + std::pow(25.0, 7))));
  const PrimedChroma p1 = primed(x, g), p2 = primed(y, g);
  // Step 2 (Eqs. 8–11): Δh′ is 0 when either colour is neutral.
  const double dl = y.L - x.L, dc = p2.c - p1.c;
  double dh = 0;
  if (p1.c * p2.c != 0) {
    dh = p2.h - p1.h;
    if (dh > 180) dh -= 360;
    else if (dh < -180) dh += 360;
  }
  const double dH = 2 * std::sqrt(p1.c * p2.c) * std::sin(dh / 2 * kDeg);
  // Step 3 (Eqs. 12–22): mean hue h̄′ per Eq. 14's four cases.
  const double lbar = (x.L + y.L) / 2, cpbar = (p1.c + p2.c) / 2;
  double hbar = p1.h + p2.h;
  if (p1.c * p2.c != 0) {
    if (std::abs(p1.h - p2.h) > 180) hbar += hbar < 360 ? 360 : -360;
    hbar /= 2;
  }
  const double t = 1 - 0.17 * std::cos((hbar - 30) * kDeg) + 0.24 * std::cos(2 * hbar * kDeg) +
                   0.32 * std::cos((3 * hbar + 6) * kDeg) - 0.20 * std::cos((4 * hbar - 63) * kDeg);
  const double dtheta = 30 * std::exp(-std::pow((hbar - 275) / 25, 2));
  const double cp7 = std::pow(cpbar, 7);
  const double rc = 2 * std::sqrt(cp7 / (cp7 + std::pow(25.0, 7)));
  const double l50 = (lbar - 50) * (lbar - 50);
  const double sl = 1 + 0.015 * l50 / std::sqrt(20 + l50), sc = 1 + 0.045 * cpbar, sh = 1 + 0.015 * cpbar * t;
  const double rt = -std::sin(2 * dtheta * kDeg) * rc;
  const double tl = dl / sl, tc = dc / sc, th = dH / sh;
  return std::sqrt(tl * tl + tc * tc + th * th + rt * tc * th);
}

}  // namespace brdfkit::render
