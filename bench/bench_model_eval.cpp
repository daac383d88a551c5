// Evaluation throughput of kd/π + Cook-Torrance for every distribution of the catalogue:
// evaluations per second on one core, through the runtime Model::eval_batch_rgb that fitting uses
// (fit/engine/projected_objective.cpp; ModelAdapter → the static type's structure-of-arrays loop,
// one virtual call per sweep: one pass for the three channels where they share their costly terms,
// as here (Cook-Torrance and Holzschuch-Pacanowski: D and G; He: its shadowing, effective
// roughness and, with η and k shared as here, its Fresnel factor), three eval_batch calls for the
// other models) over the 1 458 000 direction pairs of a MERL grid (cell centres, DESIGN.md §2),
// three channels per sweep.
// DESIGN.md §12's floor: 3.7 ms per sweep for GGX in double. Also the per-pair virtual
// Model::eval for GGX, to show what the batch loop buys, and He one channel per call.
// `--stride=k` evaluates every k-th pair only (for distributions whose Smith term is numeric,
// where a full sweep takes minutes); the rate (items_per_second = evaluations/s) is what to compare.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>
#include <tuple>
#include <vector>

#include "brdfkit/core/half_diff.h"
#include "brdfkit/measured/sample_set.h"
#include "brdfkit/models/cook_torrance_catalogue.h"
#include "brdfkit/models/model.h"

using namespace brdfkit;

namespace {

struct Grid {
  std::vector<double> wix, wiy, wiz, wox, woy, woz;
  size_t size() const { return wix.size(); }
};

size_t g_stride = 1;

// Every MERL cell at its centre in index space (θh quadratic), the directions of a full file
// (every g_stride-th of them).
const Grid& merl_grid() {
  static const Grid g = [] {
    Grid g;
    const size_t n = 90 * 90 * 180 / g_stride + 1;
    for (auto* v : {&g.wix, &g.wiy, &g.wiz, &g.wox, &g.woy, &g.woz}) v->reserve(n);
    size_t cell = 0;
    for (int ih = 0; ih < 90; ++ih)
      for (int id = 0; id < 90; ++id)
        for (int ip = 0; ip < 180; ++ip) {
          if (cell++ % g_stride != 0) continue;
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

void sweep(benchmark::State& state, std::string_view name) {
  const Grid& g = merl_grid();
  const Model& m = model_by_name(name);
  const ParamValues v = ParamValues::defaults(m.params());
  const SoaPairs d{g.wix.data(), g.wiy.data(), g.wiz.data(), g.wox.data(), g.woy.data(), g.woz.data()};
  std::vector<double> out_r(g.size()), out_g(g.size()), out_b(g.size());
  const double* const p[3] = {v.channel(0), v.channel(1), v.channel(2)};
  double* const out[3] = {out_r.data(), out_g.data(), out_b.data()};
  // One sweep before the timed ones: the tables built on first use (Smith Λ nodes and rows, He's
  // series, Holzschuch-Pacanowski's G1) would otherwise fall into the first timed iterations.
  m.eval_batch_rgb(p, g.size(), d, out);
  for (auto _ : state) {
    m.eval_batch_rgb(p, g.size(), d, out);
    benchmark::DoNotOptimize(out_r.data());
    benchmark::DoNotOptimize(out_g.data());
    benchmark::DoNotOptimize(out_b.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(int64_t(state.iterations() * 3 * g.size()));
}

// He through Model::eval_batch, one channel per call (what the fitter's per-channel Jacobian columns
// take): each call computes the shape terms that eval_batch_rgb shares between the channels.
void he_per_channel(benchmark::State& state) {
  const Grid& g = merl_grid();
  const Model& m = model_by_name("he");
  const ParamValues v = ParamValues::defaults(m.params());
  const SoaPairs d{g.wix.data(), g.wiy.data(), g.wiz.data(), g.wox.data(), g.woy.data(), g.woz.data()};
  std::vector<double> out(g.size());
  for (auto _ : state) {
    for (int c = 0; c < 3; ++c) {
      m.eval_batch(v.channel(c), c, g.size(), d, out.data());
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
  }
  state.SetItemsProcessed(int64_t(state.iterations() * 3 * g.size()));
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
  state.SetItemsProcessed(int64_t(state.iterations() * 3 * g.size()));
}

}  // namespace

int main(int argc, char** argv) {
  for (int a = 1; a < argc; ++a)
    if (std::strncmp(argv[a], "--stride=", 9) == 0) {
      g_stride = std::max(1, std::atoi(argv[a] + 9));
      for (int b = a; b + 1 < argc; ++b) argv[b] = argv[b + 1];
      --argc;
      break;
    }
  std::printf(
      "kd/pi + Cook-Torrance (Schlick F, Smith G unless noted), Model::eval_batch over %zu pairs of a MERL grid "
      "(every %zu-th) x 3 channels per iteration (Time = one sweep), one core; items_per_second = evaluations/s.\n"
      "Reproduce: cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release && ninja -C build bench_model_eval && "
      "taskset -c 0 build/bench/bench_model_eval --benchmark_min_time=1 [--stride=8]\n",
      merl_grid().size(), g_stride);
  std::apply(
      [](auto... m) {
        (benchmark::RegisterBenchmark(std::string(decltype(m)::name()).c_str(), sweep, decltype(m)::name())
             ->Unit(benchmark::kMillisecond),
         ...);
      },
      CookTorranceCatalogue{});
  // The physical models (kd/pi + their own lobe), whose series and numeric terms dominate fit-all's time.
  for (std::string_view name : {"he", "holzschuch-pacanowski", "low-microfacet"})
    benchmark::RegisterBenchmark(std::string(name).c_str(), sweep, name)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("he/Model::eval_batch-per-channel", he_per_channel)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("cook-torrance-ggx/virtual-Model::eval-per-pair", virtual_per_pair)
      ->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
