// Conjugate words (core/conjugate_words) and Jerboa orbit types
// (rewriting/jerboa_scheme): the first byte picks the model.
#include <stdexcept>

#include "core/conjugate_words.hpp"
#include "fuzz/harness.hpp"
#include "rewriting/jerboa_scheme.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dartcheck;
  if (size == 0) return 0;
  static const Model models[] = {Model::gmap(2), Model::gmap(3), Model::omap(2), Model::omap(3)};
  const Model& model = models[data[0] % 4];
  const std::string_view text = fuzzing::as_text(data + 1, size - 1);
  try {
    (void)parse_conj_word(text, model);
  } catch (const ValueError&) {
  }
  try {
    (void)parse_orbit_type(text);
  } catch (const ValueError&) {
  }
  return 0;
}
