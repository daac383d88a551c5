// Evaluation throughput of kd/π + Cook-Torrance for every distribution of the catalogue, through
// eval_batch over the 1 458 000 direction pairs of a MERL grid (cell centres, DESIGN.md §2),
// three channels per sweep, one core. DESIGN.md §12's floor: 3.7 ms per sweep for GGX in double.
// Also the per-pair virtual Model::eval for GGX, to show what the batch loop buys.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <tuple>
#include <vector>

#include "brdfkit/core/half_diff.h"
#include "brdfkit/measured/sample_set.h"
#include "brdfkit/models/cook_torrance_catalogue.h"

using namespace brdfkit;

namespace {

struct Grid {
  std::vector<double> wix, wiy, wiz, wox, woy, woz;
  size_t size() const { return wix.size(); }
};

// Every MERL cell at its centre in index space (θh quadratic), the directions of a full file.
const Grid& merl_grid() {
  static const Grid g = [] {
    Grid g;
    const size_t n = 90 * 90 * 180;
    for (auto* v : {&g.wix, &g.wiy, &g.wiz, &g.wox, &g.woy, &g.woz}) v->reserve(n);
    for (int ih = 0; ih < 90; ++ih)
      for (int id = 0; id < 90; ++id)
        for (int ip = 0; ip < 180; ++ip) {
          const double th = (ih + 0.5) / 90, td = (id + 0.5) / 90 * kPi / 2, pd = (ip + 0.5) / 180 * kPi;
          Vec3d wi, wo;
          from_half_diff({th * th * kPi / 2, 0.0, td, pd}, wi, wo);
          g.wix.push_back(wi.x());
          g.wiy.push_back(wi.y());
          g.wiz.push_back(wi.z());
          g.wox.push_back(wo.x());
          g.woy.push_back(wo.y());
          g.woz.push_back(wo.z());
        }
    return g;
  }();
  return g;
}

template <class M> void sweep(benchmark::State& state) {
  const Grid& g = merl_grid();
  const ParamValues v = ParamValues::defaults(M::params());
  std::vector<double> out(g.size());
  for (auto _ : state) {
    for (int c = 0; c < 3; ++c) {
      M::eval_batch(v.channel(c), c, g.size(), g.wix.data(), g.wiy.data(), g.wiz.data(), g.wox.data(), g.woy.data(),
                    g.woz.data(), out.data());
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
  }
  const double evals = 3.0 * double(g.size());
  state.SetItemsProcessed(int64_t(state.iterations() * evals));
  state.counters["ns_per_eval"] =
      benchmark::Counter(evals * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void virtual_per_pair(benchmark::State& state) {
  const Grid& g = merl_grid();
  const Model& m = model_by_name("cook-torrance-ggx");
  const ParamValues v = ParamValues::defaults(m.params());
  std::vector<double> out(g.size());
  for (auto _ : state) {
    for (int c = 0; c < 3; ++c) {
      for (size_t k = 0; k < g.size(); ++k)
        out[k] = m.eval(v.channel(c), c, Vec3d(g.wix[k], g.wiy[k], g.wiz[k]), Vec3d(g.wox[k], g.woy[k], g.woz[k]));
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
  }
  const double evals = 3.0 * double(g.size());
  state.SetItemsProcessed(int64_t(state.iterations() * evals));
  state.counters["ns_per_eval"] =
      benchmark::Counter(evals * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

}  // namespace

int main(int argc, char** argv) {
  std::printf(
      "kd/pi + Cook-Torrance (Schlick F, Smith G unless noted), eval_batch over the %zu pairs of a MERL grid x 3 "
      "channels per iteration (Time = one sweep), one core.\n"
      "Reproduce: cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release && ninja -C build bench_model_eval && "
      "build/bench/bench_model_eval --benchmark_min_time=1\n",
      merl_grid().size());
  std::apply(
      [](auto... m) {
        (benchmark::RegisterBenchmark(std::string(decltype(m)::name()).c_str(), sweep<decltype(m)>)
             ->Unit(benchmark::kMillisecond),
         ...);
      },
      CookTorranceCatalogue{});
  benchmark::RegisterBenchmark("cook-torrance-ggx/virtual-Model::eval-per-pair", virtual_per_pair)
      ->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
