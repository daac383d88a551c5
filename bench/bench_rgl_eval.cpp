// RGL tensor_file evaluation throughput, one core (DESIGN.md §2 evaluation: inverse VNDF warp +
// bilinear RGB look-up + D/(4σ cos θo)). Reproduce with:
//   ninja -C <build> bench_rgl_eval && <build>/bench/bench_rgl_eval --benchmark_filter=RglEval
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <random>

#include "brdfkit/measured/rgl_tensor.h"

using namespace brdfkit;

namespace {

std::filesystem::path rgl_file() { return std::filesystem::path(BRDFKIT_BENCH_DATA_DIR) / "rgl" / "satin_rosaline_rgb.bsdf"; }

void RglEval(benchmark::State& state) {
  if (!std::filesystem::exists(rgl_file())) {
    state.SkipWithError(("shared data absent: " + rgl_file().string()).c_str());
    return;
  }
  static bool printed = false;
  if (!printed) {
    std::printf("reproduce: ninja -C <build> bench_rgl_eval && <build>/bench/bench_rgl_eval --benchmark_filter=RglEval (one core: taskset -c 0)\n");
    printed = true;
  }
  const RglBrdf brdf(rgl_file());
  // 4096 fixed direction pairs, θ uniform in [0°, 80°], seeded.
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::pair<Vec3d, Vec3d>> pairs;
  for (int k = 0; k < 4096; ++k)
    pairs.emplace_back(spherical_direction(u(rng) * 1.4, 2 * kPi * u(rng)), spherical_direction(u(rng) * 1.4, 2 * kPi * u(rng)));
  size_t k = 0;
  double sink = 0;
  for (auto _ : state) {
    const auto& [wi, wo] = pairs[k++ & 4095];
    const auto v = brdf.eval(wi, wo);
    sink += (*v)[1];
    benchmark::DoNotOptimize(sink);
  }
  state.SetItemsProcessed(int64_t(state.iterations()));
  state.counters["evals_per_s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(RglEval);

}  // namespace

BENCHMARK_MAIN();
