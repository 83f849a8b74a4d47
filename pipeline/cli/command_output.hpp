#pragma once
// Where a command's output file goes: named for the format written in it,
// and written durably (durable_file.hpp) or to standard output.

#include <filesystem>
#include <optional>
#include <string_view>

namespace lc {

// Throws std::invalid_argument "-o PATH: <what> (name it <extension>)"
// unless `path` ends in `extension` (".png"; any case): a writer of one
// format must not put its bytes under another format's name.
void require_extension(const std::filesystem::path& path, std::string_view extension, std::string_view what);

// Writes `data` durably to `path`, or to standard output when no path is
// given (for commands whose output defaults to stdout).
void write_output(const std::optional<std::filesystem::path>& path, std::string_view data);

}  // namespace lc
