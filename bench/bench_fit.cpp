// Fit speed on a full-size MERL-format file (DESIGN.md §12): diffuse + Cook-Torrance/Beckmann
// tabulated from known parameters, fitted under `ngan` from the default start. Reports wall time
// of each stage and the peak RSS (getrusage). Target: the whole fit ≤ 1 s on a 2-core machine.
//
// Reproduce: ninja -C build bench_fit && ./build/bench/bench_fit --benchmark_repetitions=3
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "brdfkit/fit/metric.h"
#include "brdfkit/fit/variable_projection.h"
#include "brdfkit/measured/load.h"
#include "brdfkit/measured/merl.h"
#include "brdfkit/measured/merl_tabulate.h"
#include "brdfkit/models/model.h"

namespace {

using namespace brdfkit;

const std::filesystem::path& data_file() {
  static const std::filesystem::path file = [] {
    const auto f = std::filesystem::temp_directory_path() / "brdfkit_bench_fit_ct_beckmann.binary";
    const Model& m = model_by_name("cook-torrance-beckmann");
    ParamValues v = ParamValues::defaults(m.params());
    const double kd[3] = {0.12, 0.08, 0.05}, ks[3] = {0.9, 0.7, 0.6};
    for (int c = 0; c < 3; ++c) {
      v.set(m.params(), "kd", kd[c], c);
      v.set(m.params(), "ks", ks[c], c);
    }
    v.set(m.params(), "alpha", 0.12);
    const Brdf brdf(m, v);
    merl::write(f, merl::tabulate([&](const Vec3d& wi, const Vec3d& wo) { return brdf.eval(wi, wo); }));
    return f;
  }();
  return file;
}

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;  // kilobytes on Linux
}

void BM_FitNganCookTorranceBeckmann(benchmark::State& state) {
  const Model& model = model_by_name("cook-torrance-beckmann");
  const auto& file = data_file();
  double t_load = 0, t_domain = 0, t_fit = 0, cpu_fit = 0, alpha = 0;
  int iterations = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto data = load_measured(file);
    const auto t1 = std::chrono::steady_clock::now();
    const fit::Metric metric = fit::make_metric("ngan", *data);
    const auto t2 = std::chrono::steady_clock::now();
    const double c2 = cpu_seconds();
    const fit::FitResult r = fit::fit_model(model, metric, {});
    const auto t3 = std::chrono::steady_clock::now();
    cpu_fit = cpu_seconds() - c2;
    t_load = std::chrono::duration<double>(t1 - t0).count();
    t_domain = std::chrono::duration<double>(t2 - t1).count();
    t_fit = std::chrono::duration<double>(t3 - t2).count();
    alpha = r.values.values[0][size_t(find_param(model.params(), "alpha"))];
    iterations = r.iterations;
    benchmark::DoNotOptimize(r.metric_value);
  }
  state.counters["load_s"] = t_load;
  state.counters["domain_s"] = t_domain;
  state.counters["fit_s"] = t_fit;
  state.counters["fit_cpu_s"] = cpu_fit;  // all threads: wall time on an idle machine ≥ this / cores
  state.counters["total_s"] = t_load + t_domain + t_fit;
  state.counters["alpha"] = alpha;  // true 0.12
  state.counters["iterations"] = iterations;
  state.counters["peak_rss_MB"] = peak_rss_mb();
}
BENCHMARK(BM_FitNganCookTorranceBeckmann)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  std::printf("reproduce: ninja -C build bench_fit && ./build/bench/bench_fit --benchmark_repetitions=3\n");
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  data_file();  // tabulate once, outside the timings
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::filesystem::remove(data_file());
  return 0;
}
