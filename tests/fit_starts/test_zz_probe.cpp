// TEMPORARY probe (starts): scan on/off per model on Cornell, CPU.
#include <gtest/gtest.h>
#include <cstdio>
#include <ctime>
#include <cstdlib>
#include "brdfkit/fit/metric.h"
#include "brdfkit/fit/model_sets.h"
#include "brdfkit/fit/variable_projection.h"
#include "brdfkit/measured/load.h"
#include "test_util.h"
namespace brdfkit::fit {
TEST(ZzProbe, Cornell) {
  const char* files = std::getenv("PROBE_FILES");
  const char* models = std::getenv("PROBE_MODELS");
  std::string fl = files ? files : "acryl_blue.brdf";
  std::stringstream ss(fl);
  std::string f;
  while (std::getline(ss, f, ',')) {
    const auto data = load_measured(f.find('/') != std::string::npos ? f : (test::data_dir() / "cornell" / f).string());
    const Metric metric = make_metric("ngan", *data);
    for (const Model* m : parse_model_set(models ? models : "single-lobe")) {
      for (int scan = 0; scan < 2; ++scan) {
        FitOptions o; o.scan_start = scan;
        const std::clock_t c0 = std::clock();
        const FitResult r = fit_model(*m, metric, o);
        std::printf("%s %-32s scan %d ngan %.6g it %d pts %d cpu %.3f conv %d\n", f.c_str(), std::string(m->name()).c_str(), scan,
                    r.metric_value, r.iterations, r.scan_points, double(std::clock() - c0) / CLOCKS_PER_SEC, int(r.converged));
        std::fflush(stdout);
      }
    }
  }
}
}
#include "brdfkit/measured/merl_tabulate.h"
#include "brdfkit/measured/merl_brdf.h"
namespace brdfkit::fit {
TEST(ZzProbe, FullMerl) {
  const Model& m = model_by_name("cook-torrance-beckmann");
  ParamValues v = ParamValues::defaults(m.params());
  v.set(m.params(), "kd", 0.1); v.set(m.params(), "ks", 0.8); v.set(m.params(), "alpha", 0.12); v.set(m.params(), "F0", 0.05);
  const Brdf brdf(m, v);
  const MerlBrdf data(merl::tabulate([&](const Vec3d& wi, const Vec3d& wo) { return brdf.eval(wi, wo); }), "full.binary");
  const Metric metric = make_metric("ngan", data);
  for (int rep = 0; rep < 2; ++rep)
  for (int scan = 0; scan < 2; ++scan) {
    FitOptions o; o.scan_start = scan;
    const std::clock_t c0 = std::clock();
    const FitResult r = fit_model(m, metric, o);
    std::printf("full scan %d alpha %.9f it %d pts %d cpu %.3f wall %.3f samples %zu\n", scan, r.values.values[0][2], r.iterations, r.scan_points,
                double(std::clock() - c0) / CLOCKS_PER_SEC, r.seconds, metric.sample_count());
    std::fflush(stdout);
  }
}
}
