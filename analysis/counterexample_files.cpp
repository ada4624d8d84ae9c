#include "analysis/counterexample_files.hpp"

#include <cctype>
#include <filesystem>
#include <sstream>

#include <fmt/format.h>

#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "core/shell_quote.hpp"
#include "io/jerboa_jba.hpp"
#include "io/counterexample_file.hpp"
#include "io/map_io.hpp"

namespace dartcheck::analysis {

std::string file_stem(const std::string& name) {
  // Injective: '.' in a stem only ever comes from '/', and '%' only from
  // an escape, so two rule names never share a file.
  std::string s;
  for (const unsigned char c : name) {
    if (c == '/')
      s += '.';
    else if (std::isalnum(c) || c == '-' || c == '_' || c == '+' || c == '=' || c == ',' || c == '@')
      s += static_cast<char>(c);
    else
      s += fmt::format("%{:02X}", c);
  }
  return s;
}

namespace {

std::string replay_command(ReplayCommand what, const std::string& catalog, const std::string& rule, const std::string& host,
                           const std::vector<Dart>& hooks) {
  std::string cmd = fmt::format("dartcheck {} {} --rule {} --map {}", what == ReplayCommand::apply ? "apply" : "events", shell_quote(catalog),
                                shell_quote(rule), shell_quote(host));
  for (Dart h : hooks) cmd += fmt::format(" --hook {}", h);
  if (what == ReplayCommand::events) cmd += " --dynamic";
  return cmd;
}

}  // namespace

std::string write_counterexample(const std::string& dir, const std::string& stem_name, const std::string& catalog, const std::string& rule,
                                 const std::vector<std::pair<std::string, std::string>>& fields, const std::vector<std::string>& static_failures,
                                 const Counterexample& cx, ReplayCommand what) {
  ensure_directory(dir);
  const std::string stem = (std::filesystem::path(dir) / stem_name).string();
  write_file(stem + ".host.yaml", map_to_yaml(cx.host));
  if (cx.result) write_file(stem + ".result.yaml", map_to_yaml(*cx.result));
  const std::string replay = replay_command(what, catalog, rule, stem + ".host.yaml", cx.hooks);
  CounterexampleFile file{rule,
                          catalog,
                          fields,
                          static_failures,
                          stem + ".host.yaml",
                          cx.host.size(),
                          cx.hooks,
                          cx.match,
                          cx.result ? stem + ".result.yaml" : "",
                          cx.broken(),
                          cx.unrepresentable,
                          cx.event_contradictions,
                          {},
                          cx.origin,
                          cx.minimal,
                          replay};
  for (const auto& v : cx.violations) file.violations.push_back({v.element, constraint_name(v), describe(v, fmt::format("dart {}", v.element))});
  write_file(stem + ".counterexample.yaml", counterexample_file_text(file));
  return replay;
}

std::string write_embedding_counterexample(const std::string& dir, const std::string& stem, const std::string& catalog, const std::string& rule,
                                           const EmbeddedMap& host, const std::vector<Dart>& hooks) {
  JbaFile f{"dartcheck prove", host.map, {}, {}};
  for (const Embedding& e : host.embeddings) {
    MapEmbedding m{e.signature.name, std::string(name_of(e.signature.type)), e.signature.orbit, {}, {}};
    for (Dart d = 0; d < host.map.size(); ++d)
      if (const Value* v = e.value(d)) {
        m.values.resize(host.map.size());
        m.values[d] = jba_value(*v);
      }
    m.values.resize(host.map.size());
    f.embeddings.push_back(std::move(m));
  }
  const std::string base = (std::filesystem::path(dir) / stem).string();
  std::ostringstream text;
  try {
    write_jba(text, f, base + ".host.jba");
  } catch (const InputError&) {
    return {};  // not an n-G-map with every link set: no .jba form
  }
  write_file(base + ".host.jba", text.str());
  std::string hook_args;
  for (Dart d : hooks) hook_args += fmt::format(" --hook {}", d);
  return fmt::format("dartcheck apply {} --rule {} --map {}{} -o {}; dartcheck validate-map {}", shell_quote(catalog), shell_quote(rule),
                     shell_quote(base + ".host.jba"), hook_args, shell_quote(base + ".result.jba"), shell_quote(base + ".result.jba"));
}

std::string write_event_witness(const std::string& dir, const std::string& stem, const std::string& catalog, const std::string& rule, const Map& host,
                                const std::vector<Dart>& hooks) {
  const std::string path = (std::filesystem::path(dir) / stem).string() + ".host.yaml";
  write_file(path, map_to_yaml(host));
  std::string hook_args;
  for (Dart d : hooks) hook_args += fmt::format(" --hook {}", d);
  return fmt::format("dartcheck events {} --rule {} --map {}{} --dynamic", shell_quote(catalog), shell_quote(rule), shell_quote(path), hook_args);
}

}  // namespace dartcheck::analysis
