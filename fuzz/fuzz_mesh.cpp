// OFF meshes (io/mesh_io) and their maps (generators/mesh_map): the first
// byte picks the model, the rest is the file.
#include "checkers/map_validity.hpp"
#include "core/input_error.hpp"
#include "fuzz/harness.hpp"
#include "generators/mesh_map.hpp"
#include "io/mesh_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dartcheck;
  if (size == 0) return 0;
  const Model model = data[0] % 2 ? Model::omap(2) : Model::gmap(2);
  try {
    const Mesh mesh = read_mesh(fuzzing::input_file(data + 1, size - 1, ".off"));
    (void)check_map(build_mesh(model, mesh));
  } catch (const InputError&) {
  }
  return 0;
}
