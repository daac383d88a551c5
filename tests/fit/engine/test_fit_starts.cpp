// Start 0 of fit_model on real data: the fit's own metric value is the metric of the
// parameters it returns for every single-lobe model (Ashikhmin-Shirley's was not: its lobe is not
// scaled by a linear parameter, and the variable projection fitted kd (1/π + lobe) instead), the
// scanned start is never worse than the defaults, and the CLI reports the scan.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "brdfkit/fit/metric/metric.h"
#include "brdfkit/models/model_sets.h"
#include "brdfkit/fit/engine/fit_model.h"
#include "brdfkit/measured/load.h"
#include "support/output_lines.h"
#include "support/test_util.h"

namespace brdfkit::fit {
namespace {

std::string cornell(const char* name) { return (test::data_dir() / "cornell" / name).string(); }

TEST(FitStarts, EverySingleLobeFitReportsTheMetricOfItsParametersOnKrylonBlue) {
  BRDFKIT_REQUIRE_DATA("cornell");
  const auto data = load_measured(cornell("krylon_blue.brdf"));
  const Metric metric = make_metric("ngan", *data);
  for (const Model* m : parse_model_set("single-lobe")) {
    SCOPED_TRACE(m->name());
    const FitResult r = fit_model(*m, metric, {});
    const double recomputed = metric.value(*m, r.values);
    std::printf("%-32s ngan %.6g (recomputed %.6g), scan %d points, %d it, %.2f s\n", std::string(m->name()).c_str(),
                r.metric_value, recomputed, r.scan_points, r.iterations, r.seconds);
    EXPECT_NEAR(r.metric_value, recomputed, 1e-9 * recomputed);
    EXPECT_GT(r.scan_points, 1);
  }
}

// The scan vs the defaults (FitSettings::scan_start = false) for the models whose Cornell errors
// looked like stalls: the scan's fit is never worse (measured: equal on 7 of 9, garnet_red ward
// 0.3732 → 0.3663 and blinn-phong 0.4590 → 0.4526). Ward's 0.323 on krylon_blue is its optimum,
// not a stall (16 random starts give the same), and Ashikhmin-Shirley's 1.02 was the projection's
// kd (1/π + lobe), now 0.0968 from either start.
TEST(FitStarts, ScannedStartIsNeverWorseThanTheDefaultsOnCornell) {
  BRDFKIT_REQUIRE_DATA("cornell");
  for (const char* file : {"acryl_blue.brdf", "garnet_red.brdf", "krylon_blue.brdf"}) {
    const auto data = load_measured(cornell(file));
    const Metric metric = make_metric("ngan", *data);
    for (const char* name : {"ward", "blinn-phong", "ashikhmin-shirley"}) {
      SCOPED_TRACE(std::string(file) + " " + name);
      const Model& m = model_by_name(name);
      FitSettings defaults;
      defaults.scan_start = false;
      const FitResult plain = fit_model(m, metric, defaults), scanned = fit_model(m, metric, {});
      std::printf("%-16s %-18s ngan from the defaults %.6g, from the scan %.6g\n", file, name, plain.metric_value,
                  scanned.metric_value);
      EXPECT_EQ(plain.scan_points, 0);
      // Both fits may end at a stall (fit/stall_stop.h): in one basin a few 1e-6 apart (measured:
      // acryl_blue ashikhmin-shirley 0.676259 from the defaults, 0.676261 from the scan).
      EXPECT_LE(scanned.metric_value, plain.metric_value * (1 + 2e-5));
    }
  }
}

TEST(FitStarts, CliReportsTheScanInTheConsoleAndTheJson) {
  BRDFKIT_REQUIRE_DATA("cornell");
  const auto dir = test::scratch_dir("fit_starts_cli");
  const std::string out = (dir / "fit.json").string();
  const test::CliResult r = test::run_cli("fit " + cornell("krylon_blue.brdf") + " --model ward --report ngan -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(test::has_line(r.out, "  step     start 0 = best of 13 scan points (fit/engine/start_scan.h)")) << r.out;
  const test::CliResult j =
      test::run_cli("fit " + cornell("krylon_blue.brdf") + " --model ward --report ngan --json -o " + out);
  ASSERT_EQ(j.exit_code, 0) << j.err;
  const nlohmann::json doc = nlohmann::json::parse(j.out);
  EXPECT_EQ(doc["fit"]["start_scan_points"], 13);  // α ∈ [0.001, 1]: 3 decades, 12 points, and the defaults
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace brdfkit::fit
