#include "io/input_file.hpp"

#include <filesystem>

#include "core/input_error.hpp"

namespace dartcheck {

std::ifstream open_input(const std::string& file, std::ios::openmode mode) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto status = fs::status(file, ec);
  if (ec || !fs::exists(status)) throw InputError(file, 0, 0, "no such file");
  if (fs::is_directory(status)) throw InputError(file, 0, 0, "is a directory, not a file");
  std::ifstream in(file, mode);
  if (!in) throw InputError(file, 0, 0, "cannot open the file for reading");
  return in;
}

}  // namespace dartcheck
