// libFuzzer target: the Cornell .brdf reader (measured/cornell.h CornellBrdf) with the built-in
// CIE tables, and what the commands ask of it: samples with their solid-angle weights and the
// directional albedos computed from them. The input is the whole file.
#include "brdfkit/measured/cornell.h"
#include "fuzz_input.h"

using namespace brdfkit;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  const auto& file = fuzz::write_input(data, size);
  fuzz::expect_input_errors_naming(file, [&] {
    const CornellBrdf brdf(file);
    (void)brdf.dimensions();
    (void)brdf.samples();
    (void)brdf.albedos_from_samples();
  });
  return 0;
}
