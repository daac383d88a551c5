#pragma once
// The command-line options of FitSettings (fit/settings/fit_settings.h), bound to its fields, so
// `fit` and `fit-all` offer the same options with the same defaults and help. A setting's flag is
// its name with '-' for '_' (main.cpp maps SettingError back to it).
#include <CLI/CLI.hpp>
#include <string>

#include "brdfkit/core/error.h"
#include "brdfkit/fit/metric/metric.h"
#include "brdfkit/fit/procedure/procedure.h"
#include "brdfkit/fit/settings/fit_settings.h"

namespace brdfkit::cli {

inline void add_fit_settings(CLI::App& sub, fit::FitSettings& s) {
  auto* proc = sub.add_option("--procedure", s.procedure,
                              "Fitting procedure of the papers: " + fit::procedure_registry().listing() +
                                  " (DESIGN.md §8); its metric is the fitting metric");
  auto* metric = sub.add_option("--metric", s.metric,
                                "Plain fit under this metric: " + fit::metric_registry().listing() + " (default ngan)");
  proc->excludes(metric);
  sub.add_flag("--per-channel-shape", s.per_channel_shape,
               "Fit the lobe shape per channel instead of one shape for R, G, B");
  sub.add_option("--starts", s.starts,
                 "Number of starts: the scanned one, then seeded random ones (1 to " +
                     std::to_string(fit::FitSettings::kMaxStarts) + ")")
      ->capture_default_str();
  sub.add_option("--seed", s.seed, "Seed of the random starts")->capture_default_str();
  sub.add_option("--max-iterations", s.max_iterations,
                 "Solver iterations per start and level (1 to " + std::to_string(fit::FitSettings::kMaxIterations) +
                     ")")
      ->capture_default_str();
  sub.add_option("--coarsen", s.coarsen,
                 "Widen every metric grid step by this factor (1 = the papers' grids; quick looks only; 1 to " +
                     std::to_string(fit::FitSettings::kMaxCoarsen) + ")")
      ->capture_default_str();
  sub.add_option("--bounds")
      ->description("Search box of a parameter instead of the model's, NAME=LOWER:UPPER (repeatable; inside the "
                    "formula's domain, see `brdfkit models`; LOWER = UPPER holds it there)")
      ->take_all()
      ->type_name("NAME=LO:HI")
      ->check(CLI::Validator(
          [](std::string& v) {
            try {
              fit::parse_search_bound(v);
              return std::string();
            } catch (const SettingError& e) {
              return e.detail();
            }
          },
          ""))
      ->each([&s](const std::string& v) {
        const auto [name, box] = fit::parse_search_bound(v);
        s.bounds.insert_or_assign(name, box);
      });
  sub.add_option("--threshold", s.threshold,
                 "hp-2step: a cell is diffraction-dominated where |det(grad log rho, grad f)| < this (seed 004 §4.2)")
      ->capture_default_str();
}

}  // namespace brdfkit::cli
