// Shared by the io tests: test data paths, and the InputError position of
// a YAML map or catalog given as text.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include <gtest/gtest.h>

#include "core/input_error.hpp"
#include "io/catalog.hpp"
#include "io/map_io.hpp"
#include "io/detail/yaml_util.hpp"

namespace dartcheck::testing_support {

inline std::string data(const std::string& f) { return std::string(DARTCHECK_SOURCE_DIR) + "/tests/data/" + f; }

// Parses YAML text as if it were a file, returning the InputError position.
inline std::string error_of(const std::string& text, bool catalog = false) {
  // ctest runs each test in its own process, in parallel: one file per test.
  const auto path = std::filesystem::temp_directory_path() /
                    (std::string(catalog ? "dartcheck-test-catalog-" : "dartcheck-test-map-") +
                     ::testing::UnitTest::GetInstance()->current_test_info()->name() + "-" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(path) << text;
  try {
    if (catalog)
      read_catalog(path.string());
    else
      read_map_file(path.string());
  } catch (const InputError& e) {
    return std::to_string(e.line()) + ":" + std::to_string(e.column()) + " " + e.what();
  }
  return "no error";
}

// The message of the InputError that `read` throws, or "no error".
template <class Read>
std::string message_of(Read read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace dartcheck::testing_support
