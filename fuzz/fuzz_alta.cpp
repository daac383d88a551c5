// libFuzzer target: the ALTA θd = 0 slice reader (measured/alta_slice.h AltaSlice), its samples
// and its evaluation on and off the slice. The input is the whole .alta file.
#include "brdfkit/measured/alta_slice.h"
#include "fuzz_input.h"

using namespace brdfkit;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  const auto& file = fuzz::write_input(data, size);
  fuzz::expect_input_errors_naming(file, [&] {
    const AltaSlice brdf(file);
    (void)brdf.dimensions();
    (void)brdf.samples();
    for (const auto& [wi, wo] : fuzz::direction_pairs()) {
      (void)brdf.eval(wi, wo);
      (void)brdf.eval(wi, wi);  // on the slice
    }
  });
  return 0;
}
