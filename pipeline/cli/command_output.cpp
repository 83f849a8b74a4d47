#include "command_output.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "store/durable_file.hpp"

namespace lc {

void write_output(const std::optional<std::filesystem::path>& path, std::string_view data) {
  if (path) {
    DurableFile out(*path);
    out.write(data);
    out.commit();
    return;
  }
  if (std::fwrite(data.data(), 1, data.size(), stdout) != data.size() || std::fflush(stdout) != 0)
    throw std::runtime_error(fmt::format("cannot write to standard output: {}", std::strerror(errno)));
}

void require_extension(const std::filesystem::path& path, std::string_view extension, std::string_view what) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != extension)
    throw std::invalid_argument(fmt::format("-o {}: {} (name it {})", path.string(), what, extension));
}

}  // namespace lc
