// YAML map files (io/map_io): any text; InputError is the only answer.
#include "checkers/map_validity.hpp"
#include "core/input_error.hpp"
#include "fuzz/harness.hpp"
#include "io/map_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dartcheck;
  try {
    const Map m = read_map_file(fuzzing::input_file(data, size, ".yaml"));
    (void)check_map(m);  // a map read is a map the checker can walk
  } catch (const InputError&) {
  }
  return 0;
}
