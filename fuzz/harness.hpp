// What every libFuzzer harness shares. A reader may reject its input only
// with the error types its header documents (InputError, TermError,
// ValueError for words and orbit types); anything else that
// escapes -- another exception, a crash, a sanitizer report, a time-out --
// is a finding. Readers that take a file name get the input through a file
// of the right extension in /dev/shm (or the temporary folder).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <unistd.h>

#include "core/limits.hpp"

namespace dartcheck::fuzzing {

// Big maps are a matter of speed, not of correctness: under ASan a map of
// two million darts takes longer to check than the 10 s time-out (found by
// the first CI smoke, `darts: 2183648`). The harnesses keep maps under 4096
// darts, so the readers' limit checks are what large counts exercise.
inline const bool small_maps = [] {
  limits().darts = 4096;
  return true;
}();

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) { return {reinterpret_cast<const char*>(data), size}; }

/// A per-process file holding the input, named with `extension`.
inline std::string input_file(const std::uint8_t* data, std::size_t size, const std::string& extension) {
  static const std::filesystem::path dir = std::filesystem::exists("/dev/shm") ? "/dev/shm" : std::filesystem::temp_directory_path();
  const std::string path = (dir / ("dartcheck-fuzz-" + std::to_string(::getpid()) + extension)).string();
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

}  // namespace dartcheck::fuzzing
