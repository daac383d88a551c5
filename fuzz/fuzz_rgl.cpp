// libFuzzer target: the RGL tensor_file reader (measured/rgl_tensor.h RglBrdf) and everything a
// command does with what it returns: evaluation (single pairs, rows, luminance), the table nodes
// as samples, directional albedo. The input is the whole .bsdf file.
#include <vector>

#include "brdfkit/measured/rgl_tensor.h"
#include "fuzz_input.h"

using namespace brdfkit;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  const auto& file = fuzz::write_input(data, size);
  fuzz::expect_input_errors_naming(file, [&] {
    const RglBrdf brdf(file);
    (void)brdf.dimensions();
    std::vector<Vec3d> row;
    for (const auto& [wi, wo] : fuzz::direction_pairs()) {
      (void)brdf.eval(wi, wo);
      (void)brdf.eval_luminance(wi, wo);
      (void)brdf.table_coordinates(wi, wo);
      row.push_back(wo);
    }
    std::vector<std::optional<Rgb>> out;
    brdf.eval_row(fuzz::direction_pairs()[20].first, row, out);
    (void)brdf.albedo(spherical_direction(0.5, 0.0), 4);
    (void)brdf.samples();
    const size_t last = brdf.theta_i().size() - 1;
    const int g = brdf.grid_size() - 1;
    for (int y : {0, g})
      for (int x : {0, g}) {
        (void)brdf.rgb_node(last, y, x);
        (void)brdf.luminance_node(last, y, x);
        (void)brdf.node_directions(last, y, x);
      }
  });
  return 0;
}
