#include "core/output_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace dartcheck {

namespace fs = std::filesystem;

OutputError::OutputError(std::string file, const std::string& reason)
    : std::runtime_error(file + ": cannot write: " + reason), file_(std::move(file)) {}

void write_file(const std::string& path, std::string_view bytes) {
  // stdio rather than streams: fclose reports a write the device refused.
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw OutputError(path, std::strerror(errno));
  const bool written = bytes.empty() || std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  const int write_errno = errno;
  const bool flushed = std::fflush(f) == 0;
  const int flush_errno = errno;
  const bool closed = std::fclose(f) == 0;
  if (!written) throw OutputError(path, std::strerror(write_errno));
  if (!flushed) throw OutputError(path, std::strerror(flush_errno));
  if (!closed) throw OutputError(path, std::strerror(errno));
}

void ensure_directory(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw OutputError(dir, ec.message());
  if (!fs::is_directory(dir, ec)) throw OutputError(dir, "not a directory");
  if (::access(dir.c_str(), W_OK) != 0) throw OutputError(dir, std::strerror(errno));
}

void check_writable(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  const std::string dir = parent.empty() ? "." : parent.string();
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw OutputError(path, "the directory " + dir + " does not exist");
  if (fs::is_directory(path, ec)) throw OutputError(path, "is a directory");
  if (::access(dir.c_str(), W_OK) != 0) throw OutputError(path, std::strerror(errno));
}

}  // namespace dartcheck
