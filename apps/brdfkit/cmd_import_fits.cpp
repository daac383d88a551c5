// `brdfkit import-fits FILE.fit -o FILE.json`: published fits in the BBM benchmark's text form
// (Ngan 2005's, data/published-fits/ngan2005) written as the published-fit JSON the other
// papers' files use, with the conventions of their lobes (models/bbm_fit_text.h). Every material
// is loaded once before writing, so a file that would not load is refused whole.
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "brdfkit/core/atomic_file.h"
#include "brdfkit/core/json_text.h"
#include "brdfkit/models/bbm_fit_text.h"
#include "brdfkit/models/published_fits.h"
#include "command.h"

namespace brdfkit::cli {
namespace {

struct ImportArgs {
  std::string file, output;
};

int run_import(const ImportArgs& a) {
  if (std::filesystem::path(a.file).extension() != ".fit") throw InputError(a.file, "is not a BBM .fit text file");
  check_output_file(a.output);
  const nlohmann::json doc = read_bbm_fit_text(a.file);
  const PublishedFits fits = PublishedFits::from_document(doc, a.file);
  if (!fits.supported()) throw InputError(a.file, "unsupported: " + fits.unsupported_reason());
  for (const auto& material : fits.materials()) fits.brdf(material);
  write_file_atomically(a.output, json_text(doc) + "\n");
  std::cout << fmt::format("{} materials, model {}: wrote {}\n", fits.materials().size(), fits.model_name(), a.output);
  return 0;
}

const CommandRegistration reg("import-fits", [](CLI::App& app) {
  auto* sub = app.add_subcommand("import-fits", "Write published fits in BBM's text form (.fit) as published-fit JSON");
  auto a = std::make_shared<ImportArgs>();
  sub->add_option("FILE", a->file, "A .fit file: one 'name = Aggregate(Lambertian(...), Lobe(...))' a line")->required();
  sub->add_option("-o,--output", a->output, "The JSON file to write")->required();
  return [a]() { return run_import(*a); };
});

}  // namespace
}  // namespace brdfkit::cli
