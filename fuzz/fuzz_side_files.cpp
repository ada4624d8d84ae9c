// The side files (a byte chooses): κ files of the inference
// (io/kappa_file) and baselines (io/baseline). What reads is
// written back by dartcheck's own writer and must read back equal: a
// baseline's entries; a κ file's explicit pairs (kappa_file_text).
#include <sstream>
#include <stdexcept>

#include "core/input_error.hpp"
#include "fuzz/harness.hpp"
#include "io/kappa_file.hpp"
#include "io/baseline.hpp"

namespace {

using namespace dartcheck;

std::string file_of(const std::string& text, const char* extension) {
  return fuzzing::input_file(reinterpret_cast<const std::uint8_t*>(text.data()), text.size(), extension);
}

void baseline_round_trip(const std::string& file) {
  const Baseline b = read_baseline(file);
  std::ostringstream out;
  write_baseline(out, "fuzz", b.entries);
  const Baseline back = read_baseline(file_of(out.str(), ".yaml"));
  if (back.entries.size() != b.entries.size()) throw std::logic_error("a written baseline reads back with other entries");
  for (std::size_t k = 0; k < b.entries.size(); ++k)
    if (back.entries[k].rule != b.entries[k].rule || back.entries[k].failures != b.entries[k].failures || back.entries[k].solver != b.entries[k].solver)
      throw std::logic_error("a written baseline reads back with another entry");
}

void kappa_round_trip(const std::string& file) {
  const KappaSpec k = read_kappa_file(file, Model::gmap(2));
  if (k.identity || !k.orbits.empty()) return;  // kappa_file_text writes explicit pairs only
  const KappaSpec back = read_kappa_file(file_of(kappa_file_text(k.pairs, {"fuzz"}), ".yaml"), Model::gmap(2));
  if (back.pairs != k.pairs) throw std::logic_error("a written κ file reads back with other pairs");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  try {
    const std::string file = fuzzing::input_file(data + 1, size - 1, ".yaml");
    if (data[0] & 1)
      kappa_round_trip(file);
    else
      baseline_round_trip(file);
  } catch (const InputError&) {
  }
  return 0;
}
