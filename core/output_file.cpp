#include "core/output_file.hpp"

#include "core/error.hpp"
#include "core/input_error.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <functional>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

namespace dartcheck {

namespace fs = std::filesystem;

OutputError::OutputError(std::string file, const std::string& reason) : Error(file + ": cannot write: " + reason), file_(std::move(file)) {}

namespace {

// stdio rather than streams: fclose reports a write the device refused.
// Writes in chunks so that the test hook can stop a writer part way.
void write_stream(std::FILE* f, const std::string& name, std::string_view bytes) {
  constexpr std::size_t chunk = 1 << 16;
  for (std::size_t k = 0; k < bytes.size(); k += chunk) {
    const std::size_t n = std::min(chunk, bytes.size() - k);
    if (std::fwrite(bytes.data() + k, 1, n, f) != n) {
      const int e = errno;
      std::fclose(f);
      throw OutputError(name, std::strerror(e));
    }
    if (detail::write_hook) detail::write_hook(k + n);
  }
  if (std::fflush(f) != 0) {
    const int e = errno;
    std::fclose(f);
    throw OutputError(name, std::strerror(e));
  }
}

}  // namespace

namespace {

// ".NAME.dartcheck-PID-K": beside its target, unique in this process.
std::string fmt_temp_name(const std::string& name, unsigned k) {
  std::string r = ".";
  r += name;
  r += ".dartcheck-";
  r += std::to_string(::getpid());
  r += '-';
  r += std::to_string(k);
  return r;
}

}  // namespace

namespace detail {
std::function<void(std::size_t)> write_hook;
}

void write_file(const std::string& path, std::string_view bytes) {
  std::error_code ec;
  // A device, a FIFO or a terminal (or a link to one) is written in place:
  // a rename would replace it with a file.
  const fs::file_status st = fs::status(path, ec);
  if (!ec && fs::exists(st) && !fs::is_regular_file(st)) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) throw OutputError(path, std::strerror(errno));
    write_stream(f, path, bytes);
    if (std::fclose(f) != 0) throw OutputError(path, std::strerror(errno));
    return;
  }
  // A file: written whole beside its target, then renamed over it, so a
  // failed or interrupted write leaves the previous content (a link is
  // followed: the file it names is replaced, the link stays).
  const fs::path target = fs::is_symlink(fs::symlink_status(path, ec)) ? fs::weakly_canonical(path, ec) : fs::path(path);
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  // The permissions a new file gets (0666 less the umask), or the target's.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  struct stat old {};
  const mode_t mode = ::stat(target.c_str(), &old) == 0 ? (old.st_mode & 07777) : (0666 & ~mask);
  // An unnamed file (O_TMPFILE) gets its name only once written, so a
  // writer killed part way leaves nothing behind; where the file system
  // has none, a named temporary removed on failure.
  static std::atomic<unsigned> serial{0};
  std::string tmp = (dir / fmt_temp_name(target.filename().string(), serial++)).string();
  int fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, mode);
  const bool unnamed = fd >= 0;
  if (!unnamed) {
    fd = ::open(tmp.c_str(), O_CREAT | O_EXCL | O_WRONLY | O_CLOEXEC, mode);
    if (fd < 0) throw OutputError(path, std::strerror(errno));
  }
  struct Remove {  // the named temporary, unless renamed
    const std::string* name;
    ~Remove() {
      if (name) ::unlink(name->c_str());
    }
  } remove{unnamed ? nullptr : &tmp};
  ::fchmod(fd, mode);
  std::FILE* f = ::fdopen(fd, "wb");
  if (!f) {
    const int e = errno;
    ::close(fd);
    throw OutputError(path, std::strerror(e));
  }
  write_stream(f, path, bytes);
  if (::fsync(::fileno(f)) != 0 && errno != EINVAL) {
    const int e = errno;
    std::fclose(f);
    throw OutputError(path, std::strerror(e));
  }
  if (unnamed) {  // named now, written whole
    const std::string proc = "/proc/self/fd/" + std::to_string(::fileno(f));
    if (::linkat(AT_FDCWD, proc.c_str(), AT_FDCWD, tmp.c_str(), AT_SYMLINK_FOLLOW) != 0) {
      const int e = errno;
      std::fclose(f);
      throw OutputError(path, std::strerror(e));
    }
    remove.name = &tmp;
  }
  if (std::fclose(f) != 0) throw OutputError(path, std::strerror(errno));
  if (::rename(tmp.c_str(), target.c_str()) != 0) throw OutputError(path, std::strerror(errno));
  remove.name = nullptr;
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

void check_distinct_outputs(const std::vector<std::pair<std::string, std::string>>& outputs) {
  std::vector<std::pair<std::string, std::filesystem::path>> seen;
  for (const auto& [option, path] : outputs) {
    if (path.empty()) continue;
    std::error_code ec;
    std::filesystem::path p = std::filesystem::weakly_canonical(path, ec);
    if (ec) p = std::filesystem::absolute(path).lexically_normal();
    for (const auto& [other, q] : seen)
      if (q == p)
        throw UsageError(fmt::format("{} and {} both name '{}': one run writes each file once (give them different paths)", other, option, path));
    seen.emplace_back(option, p);
  }
}

}  // namespace dartcheck
