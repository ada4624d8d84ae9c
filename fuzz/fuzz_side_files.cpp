// The side files (a byte chooses, modulo 3): baselines (io/baseline), κ
// files of the inference (io/kappa_file) and the preserved darts apply
// records in a written map (read_recorded_kappa). What reads is written
// back by dartcheck's own writer and must read back equal: a baseline's
// entries; a κ file's explicit pairs (kappa_file_text); a map with its
// record (write_map and preserved_text).
#include <sstream>
#include <stdexcept>

#include "core/input_error.hpp"
#include "fuzz/harness.hpp"
#include "io/kappa_file.hpp"
#include "io/baseline.hpp"
#include "io/map_io.hpp"

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

void recorded_round_trip(const std::string& file) {
  const auto recorded = read_recorded_kappa(file);
  const Map map = read_map_file(file);  // the record sits in a map file that must read as one
  if (!recorded) return;
  std::ostringstream out;
  write_map(out, map);
  const std::string written = file_of(out.str() + preserved_text(recorded->pairs), ".yaml");
  const auto back = read_recorded_kappa(written);
  if (!back || back->pairs != recorded->pairs || !(read_map_file(written) == map))
    throw std::logic_error("a written map with its preserved darts reads back otherwise");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  try {
    const std::string file = fuzzing::input_file(data + 1, size - 1, ".yaml");
    switch (data[0] % 3) {  // '0', '1' and '2' in the seeds
      case 0: baseline_round_trip(file); break;
      case 1: kappa_round_trip(file); break;
      default: recorded_round_trip(file);
    }
  } catch (const InputError&) {
  }
  return 0;
}
