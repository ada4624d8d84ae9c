// Words of a command line the user pastes into a POSIX shell: a word made
// of characters no shell treats specially is written as it is, any other
// in single quotes (a quote inside as '\''), so a rule named
// `ok;$(touch x)` stays one argument and runs nothing.
#pragma once

#include <string>
#include <string_view>

namespace dartcheck {

inline std::string shell_quote(std::string_view word) {
  const bool plain =
      !word.empty() && word.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_./:=@%+,-") == std::string_view::npos;
  if (plain) return std::string(word);
  std::string out = "'";
  for (char c : word) {
    if (c == '\'')
      out += "'\\''";
    else
      out += c;
  }
  return out + "'";
}

}  // namespace dartcheck
