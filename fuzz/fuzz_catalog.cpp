// YAML rule catalogs (io/catalog): rules, schemes, Jerboa notation, terms.
#include "core/input_error.hpp"
#include "fuzz/harness.hpp"
#include "io/catalog.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dartcheck;
  try {
    (void)read_catalog(fuzzing::input_file(data, size, ".yaml"));
  } catch (const InputError&) {
  }
  return 0;
}
