#include "brdfkit/fit/model_batch.h"

#include "brdfkit/models/cook_torrance_catalogue.h"
#include "brdfkit/models/lambert.h"

namespace brdfkit::fit {

namespace {

template <class M> void batch(const double* p, int c, std::size_t n, const SoaPairs& d, double* out) {
  if constexpr (requires { M::eval_batch(p, c, n, d.wi_x, d.wi_y, d.wi_z, d.wo_x, d.wo_y, d.wo_z, out); }) {
    M::eval_batch(p, c, n, d.wi_x, d.wi_y, d.wi_z, d.wo_x, d.wo_y, d.wo_z, out);
  } else {
    for (std::size_t k = 0; k < n; ++k)
      out[k] = M::template eval<double>(p, c, Vec3d(d.wi_x[k], d.wi_y[k], d.wi_z[k]), Vec3d(d.wo_x[k], d.wo_y[k], d.wo_z[k]));
  }
}

}  // namespace

BatchEvalFn batch_eval_for(const Model& model) {
  // Names are read from the static types, so a renamed model cannot pick the wrong loop.
  if (model.name() == Lambert::name()) return &batch<Lambert>;
  if (model.name() == CookTorranceNgan::name()) return &batch<CookTorranceNgan>;
  if (model.name() == CookTorranceBeckmann::name()) return &batch<CookTorranceBeckmann>;
  if (model.name() == CookTorranceGgx::name()) return &batch<CookTorranceGgx>;
  return nullptr;
}

void eval_pairs(const Model& model, BatchEvalFn fast, const double* p, int c, std::size_t n, const SoaPairs& d,
                double* out) {
  if (fast) {
    fast(p, c, n, d, out);
    return;
  }
  for (std::size_t k = 0; k < n; ++k)
    out[k] = model.eval(p, c, Vec3d(d.wi_x[k], d.wi_y[k], d.wi_z[k]), Vec3d(d.wo_x[k], d.wo_y[k], d.wo_z[k]));
}

}  // namespace brdfkit::fit
