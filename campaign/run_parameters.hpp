// The options that change a run's results (seed, --runs, --max-darts...),
// as a shard's header records them: shards merge only when theirs agree.
// Free of JSON, so that the commands that state them stay light to build;
// campaign/shard_stream.cpp writes them as the header's "parameters".
#pragma once

#include <concepts>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace dartcheck::campaign {

/// One option and its value; an empty optional is recorded as null.
struct Parameter {
  using Value = std::variant<std::monostate, bool, std::int64_t, std::uint64_t, double, std::string, std::vector<std::string>>;

  Parameter(std::string n, bool v) : name(std::move(n)), value(v) {}
  Parameter(std::string n, std::signed_integral auto v) : name(std::move(n)), value(std::int64_t(v)) {}
  Parameter(std::string n, std::unsigned_integral auto v) : name(std::move(n)), value(std::uint64_t(v)) {}
  Parameter(std::string n, double v) : name(std::move(n)), value(v) {}
  Parameter(std::string n, std::string v) : name(std::move(n)), value(std::move(v)) {}
  Parameter(std::string n, const char* v) : name(std::move(n)), value(std::string(v)) {}
  Parameter(std::string n, std::vector<std::string> v) : name(std::move(n)), value(std::move(v)) {}
  template <class T>
  Parameter(std::string n, const std::optional<T>& v) : Parameter(std::move(n), v ? Parameter("", *v).value : Value()) {}

  std::string name;
  Value value;

 private:
  Parameter(std::string n, Value v) : name(std::move(n)), value(std::move(v)) {}
};

/// In the order the header lists them.
using Parameters = std::vector<Parameter>;

}  // namespace dartcheck::campaign
