#pragma once
/// @file
/// Whole-file reads and writes shared by the mesh readers and writers.

#include <filesystem>
#include <string>
#include <string_view>

namespace tailor {

/// Reads the whole file into memory. Throws InputError "cannot open" naming the path if
/// it is missing, is a directory or cannot be read, and InputError if it is larger than
/// the memory budget (memory_budget.hpp). Parsers should prefer InputFile (a mapping).
std::string read_file_bytes(const std::filesystem::path& path);

/// Makes `folder` (and its parents) exist as a writable folder, so that a command can
/// check its output location before it does any work. Throws InputError naming the
/// folder if it is a file, cannot be created, or is not writable.
void prepare_output_folder(const std::filesystem::path& folder);

/// Writes `bytes` to the file (replacing it). Throws InputError naming the path if the
/// file cannot be created or written.
void write_file_bytes(const std::filesystem::path& path, std::string_view bytes);

/// Writes `bytes` to `path.tmp`, then renames it over `path`, so a reader never sees
/// half a file. Throws InputError naming the path on failure.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace tailor
