#include "reports/json_document.hpp"

namespace dartcheck::reports {

namespace {

// The length of the well-formed UTF-8 sequence at s[k], 0 if none starts
// there (Unicode 15, Table 3-7).
std::size_t sequence_length(std::string_view s, std::size_t k) {
  const auto at = [&](std::size_t i) { return i < s.size() ? static_cast<unsigned char>(s[i]) : 0u; };
  const unsigned c = at(k);
  const auto cont = [&](std::size_t i, unsigned lo = 0x80, unsigned hi = 0xBF) { return at(i) >= lo && at(i) <= hi; };
  if (c < 0x80) return 1;
  if (c >= 0xC2 && c <= 0xDF) return cont(k + 1) ? 2 : 0;
  if (c == 0xE0) return cont(k + 1, 0xA0, 0xBF) && cont(k + 2) ? 3 : 0;
  if ((c >= 0xE1 && c <= 0xEC) || c == 0xEE || c == 0xEF) return cont(k + 1) && cont(k + 2) ? 3 : 0;
  if (c == 0xED) return cont(k + 1, 0x80, 0x9F) && cont(k + 2) ? 3 : 0;  // no surrogates
  if (c == 0xF0) return cont(k + 1, 0x90, 0xBF) && cont(k + 2) && cont(k + 3) ? 4 : 0;
  if (c >= 0xF1 && c <= 0xF3) return cont(k + 1) && cont(k + 2) && cont(k + 3) ? 4 : 0;
  if (c == 0xF4) return cont(k + 1, 0x80, 0x8F) && cont(k + 2) && cont(k + 3) ? 4 : 0;
  return 0;
}

std::size_t sanitise(Json& j) {
  std::size_t changed = 0;
  if (j.is_string()) {
    auto& s = j.get_ref<std::string&>();
    if (!valid_utf8(s)) s = replace_invalid_utf8(s), ++changed;
  } else if (j.is_object()) {
    bool bad_key = false;
    for (auto& [key, value] : j.items()) {
      changed += sanitise(value);
      bad_key |= !valid_utf8(key);
    }
    if (bad_key) {
      // Keys are names too (e.g. a rule name as a key): rebuilt, in order,
      // only when one of them is not UTF-8.
      Json copy = Json::object();
      for (auto& [key, value] : j.items()) {
        const bool bad = !valid_utf8(key);
        changed += bad;
        copy[bad ? replace_invalid_utf8(key) : key] = std::move(value);
      }
      j = std::move(copy);
    }
  } else if (j.is_array()) {
    for (auto& value : j) changed += sanitise(value);
  }
  return changed;
}

}  // namespace

bool valid_utf8(std::string_view s) {
  for (std::size_t k = 0; k < s.size();) {
    const std::size_t n = sequence_length(s, k);
    if (n == 0) return false;
    k += n;
  }
  return true;
}

std::string replace_invalid_utf8(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  bool in_bad = false;
  for (std::size_t k = 0; k < s.size();) {
    const std::size_t n = sequence_length(s, k);
    if (n == 0) {
      if (!in_bad) out += "\xEF\xBF\xBD";
      in_bad = true;
      ++k;
      continue;
    }
    in_bad = false;
    out.append(s.substr(k, n));
    k += n;
  }
  return out;
}

Json json_document(std::string_view command) {
  Json j = Json::object();
  j["format"] = "dartcheck-" + std::string(command);
  j["format_version"] = json_format_version;
  return j;
}

std::string json_text(Json document, int indent) {
  const std::size_t changed = sanitise(document);
  if (changed > 0 && document.is_object()) {
    // SARIF allows no property of its own at the top: the count goes in
    // the run's property bag there (OASIS 2.1.0 Sec. 3.8).
    const bool sarif = document.contains("runs") && document["runs"].is_array() && !document["runs"].empty();
    (sarif ? document["runs"][0]["properties"] : document)["replaced_invalid_utf8"] = changed;
  }
  return document.dump(indent);
}

}  // namespace dartcheck::reports
