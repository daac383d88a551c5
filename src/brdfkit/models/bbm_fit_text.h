#pragma once
// The BBM benchmark's text form of published fits (bsdfbenchmark/bbm `fits/*.fit`, the form of
// data/published-fits/ngan2005/): '#' comment lines, then one material a line,
//   name = Aggregate(Lambertian(albedo = [r, g, b]), Lobe(key = value or [r, g, b], ...))
// read into the published-fit JSON document that PublishedFits reads (models/published_fits.h):
// {"source", "conventions", "materials": {name: [{"lobe", "params"}, ...]}}, values as written.
// The conventions of Ngan 2005's lobes (seed 002) travel with the document; each is justified by
// a number in tests/models/test_ngan_published_fits.cpp.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace brdfkit {

// Throws InputError naming the file and line for what does not parse (an unbalanced bracket, a
// value that is not a finite number, a material named twice, no material at all).
nlohmann::json read_bbm_fit_text(const std::filesystem::path& file);

// The conventions object of a document whose specular lobe is `lobe` (e.g. "NganWard"); empty
// when the lobe is not one of Ngan 2005's.
nlohmann::json ngan2005_conventions(const std::string& lobe);

}  // namespace brdfkit
