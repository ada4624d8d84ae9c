#include "reports/html_page.hpp"

#include <array>
#include <cctype>

namespace dartcheck::reports {

std::string html_text(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '"')
      out += "&quot;";
    // XML 1.0 forbids control characters but tab and newline: a space.
    else if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t')
      out += ' ';
    else
      out += c;
  }
  return out;
}

std::string html_id(std::string_view name) {
  std::string out;
  for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.' ? c : '-';
  return out;
}

std::string inline_svg(std::string_view svg, std::string_view id_prefix) {
  const auto start = svg.find("<svg");
  std::string_view body = start == std::string_view::npos ? svg : svg.substr(start);
  std::string out;
  out.reserve(body.size() + 256);
  for (std::size_t at = 0; at < body.size();) {
    if (body.compare(at, 4, "<!--") == 0) {
      const auto end = body.find("-->", at);
      at = end == std::string_view::npos ? body.size() : end + 3;
      continue;
    }
    // Graphviz writes ids as id="node1", references as url(#...) or
    // xlink:href="#...": prefix all three.
    static constexpr std::array<std::string_view, 3> refs = {" id=\"", "url(#", "href=\"#"};
    bool prefixed = false;
    for (std::string_view attr : refs)
      if (body.compare(at, attr.size(), attr) == 0) {
        out += attr;
        out += id_prefix;
        at += attr.size();
        prefixed = true;
        break;
      }
    if (!prefixed) out += body[at++];
  }
  return out;
}

std::string html_document(std::string_view title, std::string_view body) {
  static constexpr std::string_view style = R"(
body { font-family: Helvetica, Arial, sans-serif; margin: 1.5em 2em; color: #212121; background: #ffffff; }
h1 { font-size: 1.5em; } h2 { font-size: 1.2em; margin-top: 2.2em; border-top: 1px solid #bdbdbd; padding-top: 0.8em; }
h3 { font-size: 1em; margin-bottom: 0.3em; }
table { border-collapse: collapse; margin: 0.6em 0; }
th, td { border: 1px solid #d0d0d0; padding: 0.2em 0.5em; text-align: left; vertical-align: top; font-size: 0.9em; }
th { background: #eeeeee; }
td.ok { background: #e8f5e9; } td.fails { background: #ffebee; } td.skipped, td.none { color: #757575; }
td.bug { background: #d50000; color: #ffffff; font-weight: bold; }
a { color: #1565c0; text-decoration: none; } a:hover { text-decoration: underline; }
.picture { overflow-x: auto; margin: 0.6em 0; } .picture svg { max-width: 100%; height: auto; }
.figure { margin: 0.6em 0; } .figure svg { max-width: 100%; height: auto; }
.panels { display: flex; flex-wrap: wrap; align-items: flex-start; gap: 0.5em 1.5em; }
pre { white-space: pre-wrap; }
.note { color: #616161; font-style: italic; } code { font-size: 0.9em; background: #f5f5f5; padding: 0 0.2em; }
ul.witnesses li { margin: 0.2em 0; } .mismatch { color: #b71c1c; font-weight: bold; }
)";
  std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n<title>";
  out += html_text(title);
  out += "</title>\n<style>";
  out += style;
  out += "</style>\n</head>\n<body>\n";
  out += body;
  out += "</body>\n</html>\n";
  return out;
}

}  // namespace dartcheck::reports
