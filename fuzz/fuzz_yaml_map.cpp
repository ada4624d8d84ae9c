// YAML map files (io/map_io): any text; InputError is the only answer. A
// map that reads is written back (map_to_yaml) and must read back equal.
#include <stdexcept>

#include "checkers/map_validity.hpp"
#include "core/input_error.hpp"
#include "fuzz/harness.hpp"
#include "io/map_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dartcheck;
  try {
    const Map m = read_map_file(fuzzing::input_file(data, size, ".yaml"));
    (void)check_map(m);  // a map read is a map the checker can walk
    const std::string yaml = map_to_yaml(m);
    if (!(read_map_file(fuzzing::input_file(reinterpret_cast<const std::uint8_t*>(yaml.data()), yaml.size(), ".yaml")) == m))
      throw std::logic_error("map_to_yaml does not read back");
  } catch (const InputError&) {
  }
  return 0;
}
