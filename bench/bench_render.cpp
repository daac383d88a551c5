// Render speed, one core: a 256 x 256 sphere at 64 spp under ../shared/data/envmaps/studio.exr
// (a synthetic sky when absent) of a fitted model (GGX with the parameters `brdfkit fit` finds on
// vch_golden_yellow) and of an RGL measurement (vch_golden_yellow, sampled through that fit), the
// estimator of render/sphere_renderer.h. Targets: model <= 3 s, RGL <= 10 s.
// Reproduce with:
//   ninja -C <build> bench_render && <build>/bench/bench_render
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <cstdio>
#include <filesystem>

#include "brdfkit/fit/param_source.h"
#include "brdfkit/measured/load.h"
#include "brdfkit/render/image_io.h"
#include "brdfkit/render/sphere_renderer.h"

using namespace brdfkit;
using namespace brdfkit::render;

namespace {

const std::filesystem::path kData = BRDFKIT_BENCH_DATA_DIR;

Scene studio() {
  Scene s;
  const auto map = kData / "envmaps" / "studio.exr";
  if (std::filesystem::exists(map)) {
    s.environment = EnvironmentMap(read_hdr_image(map), 0, 1);
  } else {
    Image sky(64, 32);
    for (auto& p : sky.pixels) p = Rgb(0.5, 0.6, 0.8);
    s.environment = EnvironmentMap(sky, 0, 1);
  }
  return s;
}

Brdf fitted_ggx() {
  const Model& m = model_by_name("cook-torrance-ggx");
  ParamValues v = ParamValues::defaults(m.params());
  for (const char* p : {"kd=0.14,0.09,0.004", "ks=0.41,0.35,0.10", "alpha=0.116"}) fit::apply_param(m.params(), v, p);
  return Brdf(m, v);
}

RenderSettings settings() {
  RenderSettings s;
  s.width = s.height = 256;
  s.spp = 64;
  return s;
}

void run(benchmark::State& state, const Reflector& r, const char* what) {
  tbb::global_control one_core(tbb::global_control::max_allowed_parallelism, 1);
  const Scene scene = studio();
  for (auto _ : state) benchmark::DoNotOptimize(render_sphere(r, scene, settings()).radiance.pixels.data());
  std::printf("%s: 256x256 at 64 spp on one thread (see the Time column, per render)\n", what);
}

void RenderFittedModel(benchmark::State& state) { run(state, *model_reflector(fitted_ggx()), "fitted GGX model"); }

void RenderRglMeasurement(benchmark::State& state) {
  const auto file = kData / "rgl" / "vch_golden_yellow_rgb.bsdf";
  if (!std::filesystem::exists(file)) {
    state.SkipWithError(("shared data absent: " + file.string()).c_str());
    return;
  }
  const auto data = load_measured(file);
  run(state, *measured_reflector(*data, fitted_ggx()), "RGL vch_golden_yellow");
}

}  // namespace

BENCHMARK(RenderFittedModel)->Unit(benchmark::kSecond)->Iterations(2);
BENCHMARK(RenderRglMeasurement)->Unit(benchmark::kSecond)->Iterations(1);

int main(int argc, char** argv) {
  std::printf("reproduce: ninja -C <build> bench_render && <build>/bench/bench_render\n");
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
