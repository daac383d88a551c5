// libFuzzer target: the saved-fit reader (fit/fit_record.h load_fit_record), the BRDF it names,
// and its round trip: a record that was read must be written (to_json, json_text) and read back to
// the same model and values, as `brdfkit fit` output is. The input is the whole JSON file.
#include <cstdlib>

#include "brdfkit/core/json_text.h"
#include "brdfkit/fit/fit_record.h"
#include "fuzz_input.h"

using namespace brdfkit;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  const auto& file = fuzz::write_input(data, size);
  fuzz::expect_input_errors_naming(file, [&] {
    const fit::FitRecord r = fit::load_fit_record(file);
    const Model& model = model_by_name(r.model);
    const Brdf brdf(model, r.values);
    for (const auto& [wi, wo] : fuzz::direction_pairs()) (void)brdf.eval(wi, wo);
    (void)fit::format_params(model, r.values);
    (void)fit::format_metrics(r.metrics);
    const std::string written = json_text(fit::to_json(r));
    const fit::FitRecord back = fit::fit_record_from_json(nlohmann::json::parse(written), "round trip");
    if (back.model != r.model || back.values.values != r.values.values) std::abort();
  });
  return 0;
}
