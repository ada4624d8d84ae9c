// Jerboa modelers (.jme, io/jerboa_modeler).
#include "core/input_error.hpp"
#include "fuzz/harness.hpp"
#include "io/jerboa_modeler.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dartcheck;
  try {
    (void)read_jme(fuzzing::input_file(data, size, ".jme"));
  } catch (const InputError&) {
  }
  return 0;
}
