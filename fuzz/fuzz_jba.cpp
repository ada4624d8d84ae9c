// Jerboa G-maps (.jba, io/jerboa_jba).
#include "checkers/map_validity.hpp"
#include "core/input_error.hpp"
#include "fuzz/harness.hpp"
#include "io/jerboa_jba.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dartcheck;
  try {
    const JbaFile f = read_jba(fuzzing::input_file(data, size, ".jba"));
    (void)check_map(f.map);
  } catch (const InputError&) {
  }
  return 0;
}
