// The catalogue: every model brdfkit knows, in the order `brdfkit models` lists them.
#include <string>

#include "brdfkit/core/error.h"
#include "brdfkit/models/lambert.h"
#include "brdfkit/models/model.h"

namespace brdfkit {

namespace {
template <class M> const Model* instance() {
  static const ModelAdapter<M> m;
  return &m;
}
}  // namespace

std::span<const Model* const> all_models() {
  static const Model* const models[] = {
      instance<Lambert>(),
  };
  return models;
}

const Model& model_by_name(std::string_view name) {
  std::string known;
  for (const Model* m : all_models()) {
    if (m->name() == name) return *m;
    known += (known.empty() ? "" : ", ") + std::string(m->name());
  }
  throw InputError("model '" + std::string(name) + "'", "unknown; known models: " + known);
}

}  // namespace brdfkit
