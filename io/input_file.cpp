#include "io/input_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

#include "core/input_error.hpp"
#include "core/limits.hpp"

namespace dartcheck {

std::ifstream open_input(const std::string& file, std::ios::openmode mode) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto status = fs::status(file, ec);
  if (ec == std::errc::too_many_symbolic_link_levels) throw InputError(file, 0, 0, "a loop of symbolic links, not a file");
  if (ec && ec != std::errc::no_such_file_or_directory) throw InputError(file, 0, 0, fmt::format("cannot reach the file: {}", ec.message()));
  if (ec || !fs::exists(status)) throw InputError(file, 0, 0, "no such file");
  if (fs::is_directory(status)) throw InputError(file, 0, 0, "is a directory, not a file");
  if (fs::is_character_file(status) || fs::is_block_file(status)) throw InputError(file, 0, 0, "is a device, not a file");
  std::ifstream in(file, mode);
  if (!in) throw InputError(file, 0, 0, fmt::format("cannot open the file for reading: {}", std::strerror(errno)));
  return in;
}

std::string read_input(const std::string& file) {
  std::ifstream in = open_input(file, std::ios::binary);
  const std::size_t limit = limits().file_bytes;
  const auto too_large = [&](std::size_t bytes) {
    return InputError(file, 0, 0, over_limit("bytes of the file", bytes, limit, "--limit-file-bytes"));
  };
  std::string out;
  std::error_code ec;
  if (const auto size = std::filesystem::file_size(file, ec); !ec) {
    if (size > limit) throw too_large(size);
    out.reserve(size);
  }
  char block[1 << 16];
  while (in.read(block, sizeof block) || in.gcount() > 0) {
    out.append(block, static_cast<std::size_t>(in.gcount()));
    if (out.size() > limit) throw too_large(out.size());  // a FIFO, or a file that grows
  }
  if (in.bad()) throw InputError(file, 0, 0, fmt::format("read error: {}", std::strerror(errno)));
  return out;
}

void refuse_nul_bytes(const std::string& file, std::string_view text, std::string_view what) {
  const std::size_t at = text.find('\0');
  if (at == std::string_view::npos) return;
  const std::size_t line_start = text.rfind('\n', at) == std::string_view::npos ? 0 : text.rfind('\n', at) + 1;
  const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n');
  throw InputError(file, static_cast<int>(line), static_cast<int>(at - line_start + 1), fmt::format("a NUL byte: {} is text", what));
}

}  // namespace dartcheck
