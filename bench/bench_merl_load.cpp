// MERL loading speed against the floor (reading the file's bytes), and look-up throughput.
// Target (DESIGN.md §12 spirit, task a1): merl::read ≤ 2× the time to fread the raw bytes.
// Reproduce: build/bench_merl_load   (writes /tmp/brdfkit_bench_merl.binary once, warm page cache)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <random>
#include <vector>

#include "brdfkit/measured/merl.h"
#include "brdfkit/measured/merl_tabulate.h"

using namespace brdfkit;

namespace {

const std::filesystem::path kFile = std::filesystem::temp_directory_path() / "brdfkit_bench_merl.binary";

// A full-size file with the shape of a real material (Lambert + a Beckmann-like lobe).
void ensure_file() {
  if (std::filesystem::exists(kFile) && std::filesystem::file_size(kFile) == merl::kFileBytes) return;
  merl::write(kFile, merl::tabulate([](const Vec3d& wi, const Vec3d& wo) -> Rgb {
                const Vec3d h = (wi + wo).normalized();
                const double t2 = (1 - h.z() * h.z()) / (h.z() * h.z()), a2 = 0.04;
                const double d = std::exp(-t2 / a2) / (kPi * a2 * std::pow(h.z(), 4));
                return Rgb(0.3, 0.2, 0.1) * kInvPi + Rgb::Constant(0.2 * d / (4 * wi.z() * wo.z() + 1e-3));
              }));
}

// The floor: one fread of the whole file into a freshly allocated buffer (as the loader allocates).
size_t read_raw_bytes() {
  auto buf = std::make_unique_for_overwrite<char[]>(merl::kFileBytes);
  std::FILE* f = std::fopen(kFile.c_str(), "rb");
  const size_t n = std::fread(buf.get(), 1, merl::kFileBytes, f);
  std::fclose(f);
  benchmark::DoNotOptimize(buf.get());
  return n;
}

void BM_ReadRawBytes(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(read_raw_bytes());
  state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(merl::kFileBytes));
}
BENCHMARK(BM_ReadRawBytes)->Unit(benchmark::kMillisecond);

void BM_MerlRead(benchmark::State& state) {
  for (auto _ : state) {
    merl::Table t = merl::read(kFile);
    benchmark::DoNotOptimize(t.raw_data());
  }
  state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(merl::kFileBytes));
}
BENCHMARK(BM_MerlRead)->Unit(benchmark::kMillisecond);

std::vector<std::pair<Vec3d, Vec3d>> random_pairs(size_t n) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::pair<Vec3d, Vec3d>> pairs(n);
  for (auto& [wi, wo] : pairs) {
    wi = spherical_direction(std::acos(u(rng)), 2 * kPi * u(rng));
    wo = spherical_direction(std::acos(u(rng)), 2 * kPi * u(rng));
  }
  return pairs;
}

void BM_LookupDirections(benchmark::State& state) {
  const merl::Table t = merl::read(kFile);
  const auto pairs = random_pairs(1 << 16);
  size_t k = 0;
  for (auto _ : state) {
    const auto& [wi, wo] = pairs[k++ & (pairs.size() - 1)];
    benchmark::DoNotOptimize(t.lookup(wi, wo));
  }
  state.SetItemsProcessed(int64_t(state.iterations()));
}
BENCHMARK(BM_LookupDirections);

void BM_LookupAngles(benchmark::State& state) {
  const merl::Table t = merl::read(kFile);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec3d> angles(1 << 16);
  for (auto& a : angles) a = Vec3d(u(rng) * kPi / 2, u(rng) * kPi / 2, (2 * u(rng) - 1) * kPi);
  size_t k = 0;
  for (auto _ : state) {
    const Vec3d& a = angles[k++ & (angles.size() - 1)];
    benchmark::DoNotOptimize(t.lookup(a[0], a[1], a[2]));
  }
  state.SetItemsProcessed(int64_t(state.iterations()));
}
BENCHMARK(BM_LookupAngles);

void BM_LookupTrilinearDirections(benchmark::State& state) {
  const merl::Table t = merl::read(kFile);
  const auto pairs = random_pairs(1 << 16);
  size_t k = 0;
  for (auto _ : state) {
    const auto& [wi, wo] = pairs[k++ & (pairs.size() - 1)];
    benchmark::DoNotOptimize(t.lookup_trilinear(wi, wo));
  }
  state.SetItemsProcessed(int64_t(state.iterations()));
}
BENCHMARK(BM_LookupTrilinearDirections);

// Median of interleaved repetitions of both, so page-cache and frequency drift hit both alike.
void print_ratio() {
  using clock = std::chrono::steady_clock;
  std::vector<double> raw, load;
  for (int rep = 0; rep < 15; ++rep) {
    auto t0 = clock::now();
    benchmark::DoNotOptimize(read_raw_bytes());
    auto t1 = clock::now();
    merl::Table t = merl::read(kFile);
    benchmark::DoNotOptimize(t.raw_data());
    auto t2 = clock::now();
    raw.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    load.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
  }
  auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  const double r = median(raw), l = median(load);
  std::printf("MERL file %s (%zu bytes), median of 15 interleaved runs:\n", kFile.c_str(), size_t(merl::kFileBytes));
  std::printf("  fread of the raw bytes: %.2f ms; merl::read (read + validate + mask): %.2f ms; ratio %.2f (target <= 2)\n",
              r, l, l / r);
}

}  // namespace

int main(int argc, char** argv) {
  std::printf("reproduce: build/bench_merl_load\n");
  ensure_file();
  print_ratio();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
