// A per-dart table of small integers that is empty (every entry `none`)
// between uses. set() records the darts it touches and clear() resets only
// those, so one table kept across many small applications on a large map
// costs the darts each application touches, not the size of the map (the
// role of CGAL's reserved marks). The table grows with the map.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/map.hpp"

namespace dartcheck {

class DartTable {
 public:
  static constexpr std::uint32_t none = 0xffffffffU;

  std::uint32_t get(Dart d) const { return d < entry_.size() ? entry_[d] : none; }
  void set(Dart d, std::uint32_t x) {
    if (d >= entry_.size()) entry_.resize(std::max<std::size_t>(d + 1, entry_.size() * 3 / 2), none);
    if (entry_[d] == none) touched_.push_back(d);
    entry_[d] = x;
  }
  /// Empties the table in time proportional to the darts set since the
  /// last clear.
  void clear() {
    for (Dart d : touched_) entry_[d] = none;
    touched_.clear();
  }
  /// Clears the table when it leaves scope: every return path of a user
  /// hands the table back empty.
  struct ClearOnExit {
    DartTable& table;
    ~ClearOnExit() { table.clear(); }
  };

 private:
  std::vector<std::uint32_t> entry_;
  std::vector<Dart> touched_;
};

}  // namespace dartcheck
