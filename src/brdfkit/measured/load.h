#pragma once
// Opens any supported measured file, recognized by its content first and its extension second:
// MERL `.binary` (int32 header 90 90 180), RGL `tensor_file` (`.bsdf`, magic "tensor_file\0"),
// Cornell scattered samples (`.brdf`), ALTA slices (`.alta`, "#DIM" header).
#include <filesystem>
#include <memory>
#include <string>

#include "brdfkit/measured/measured_brdf.h"

namespace brdfkit {

enum class MeasuredFormat { Merl, Rgl, Cornell, Alta, Unknown };

// What the file looks like (reads at most its first 64 bytes). Throws InputError when the file is
// missing, a directory or unreadable.
MeasuredFormat detect_measured_format(const std::filesystem::path& file);

// Reads the file with the reader of its format; InputError naming the file and the problem.
std::unique_ptr<MeasuredBrdf> load_measured(const std::filesystem::path& file);

// True for the extensions load_measured recognizes (used to list a data folder).
bool has_measured_extension(const std::filesystem::path& file);

}  // namespace brdfkit
