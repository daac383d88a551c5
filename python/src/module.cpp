// The extension module behind `import brdfkit` (python/brdfkit/__init__.py).
#include "python_api.h"

PYBIND11_MODULE(_brdfkit, m) {
  m.doc() = "brdfkit's C++ library; use the package `brdfkit`, which wraps and documents it.";
  m.attr("__version__") = BRDFKIT_VERSION;
  using namespace brdfkit::python;
  bind_errors(m);
  bind_measured(m);
  bind_models(m);
  bind_fit(m);
  bind_batch(m);
  bind_render(m);
  bind_export(m);
}
