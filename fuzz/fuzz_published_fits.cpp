// libFuzzer target: the published-fits reader (models/published_fits.h PublishedFits) as the CLI
// reaches it through fit::load_params (--params FILE --material NAME): the file, its material
// list, each material's BRDF (at most 8) and an evaluation of it. The input is the whole file.
#include <algorithm>

#include "brdfkit/fit/param_source.h"
#include "brdfkit/models/published_fits.h"
#include "fuzz_input.h"

using namespace brdfkit;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  const auto& file = fuzz::write_input(data, size);
  fuzz::expect_input_errors_naming(file, [&] {
    const PublishedFits fits = PublishedFits::read(file);
    (void)fits.stem();
    const std::vector<std::string> names = fits.materials();
    for (size_t k = 0; k < std::min<size_t>(names.size(), 8); ++k)
      fuzz::expect_input_errors_naming(file, [&] {
        const Brdf brdf = fits.brdf(names[k]);
        for (const auto& [wi, wo] : fuzz::direction_pairs()) (void)brdf.eval(wi, wo);
      });
    if (!names.empty()) (void)fit::load_params(file, names.front());
  });
  return 0;
}
