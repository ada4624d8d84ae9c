#include "core/input_error.hpp"

#include <fmt/format.h>

namespace dartcheck {

static std::string position(const std::string& file, int line, int column) {
  if (line <= 0) return file;
  return column > 0 ? fmt::format("{}:{}:{}", file, line, column) : fmt::format("{}:{}", file, line);
}

InputError::InputError(std::string file, int line, int column, const std::string& message)
    : std::runtime_error(position(file, line, column) + ": " + message), file_(std::move(file)), line_(line), column_(column) {}

std::string SourceLocation::str() const { return fmt::format("{}:{}:{}", file, line, column); }

}  // namespace dartcheck
