// The C++ side of bench/python_eval.py: Model::eval_batch (one call per channel over
// structure-of-arrays pairs, DESIGN.md §12) on the direction pairs the script wrote, best of 5,
// printed as seconds. Not a Google Benchmark: it times exactly the pairs Python evaluates.
//
// Reproduce: python3 bench/python_eval.py (builds nothing; needs build/bench/eval_pairs_baseline)
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <vector>

#include "brdfkit/core/param.h"
#include "brdfkit/models/model.h"

int main(int argc, char** argv) {
  using namespace brdfkit;
  if (argc != 4) {
    std::fprintf(stderr, "usage: eval_pairs_baseline PAIRS.f64 N MODEL  (pairs: N rows of wi, wo as float64)\n");
    return 2;
  }
  const size_t n = std::stoul(argv[2]);
  std::vector<double> aos(6 * n);
  std::ifstream in(argv[1], std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(aos.data()), std::streamsize(aos.size() * sizeof(double)))) {
    std::fprintf(stderr, "%s: expected %zu float64 values\n", argv[1], aos.size());
    return 2;
  }
  std::vector<std::vector<double>> soa(6, std::vector<double>(n));
  for (size_t k = 0; k < n; ++k)
    for (size_t d = 0; d < 6; ++d) soa[d][k] = aos[6 * k + d];
  const Model& model = model_by_name(argv[3]);
  const ParamValues values = ParamValues::defaults(model.params());
  const SoaPairs pairs{soa[0].data(), soa[1].data(), soa[2].data(), soa[3].data(), soa[4].data(), soa[5].data()};
  std::vector<double> out(n);
  double best = 1e30, sum = 0;
  for (int rep = 0; rep < 5; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int c = 0; c < 3; ++c) {
      model.eval_batch(values.channel(c), c, n, pairs, out.data());
      sum += out[n / 2];
    }
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::printf("%.6f %g\n", best, sum);
  return 0;
}
