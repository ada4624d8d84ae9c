#include "reports/svg_figure.hpp"

#include <algorithm>
#include <charconv>
#include <stdexcept>

#include <fmt/format.h>

#include "core/error.hpp"
#include "reports/html_page.hpp"

namespace dartcheck::reports {

namespace {

constexpr double gap = 18;  // points between panels and below the head

// The value of attribute `name` in the tag text `tag` (empty when it has
// none), and in `at` where the attribute starts.
std::string_view attribute(std::string_view tag, std::string_view name, std::size_t* at = nullptr) {
  const std::string key = fmt::format(" {}=\"", name);
  const auto start = tag.find(key);
  if (start == std::string_view::npos) return {};
  const auto end = tag.find('"', start + key.size());
  if (end == std::string_view::npos) return {};
  if (at) *at = start;
  return tag.substr(start + key.size(), end - start - key.size());
}

double points(std::string_view value) {
  if (value.ends_with("pt")) value.remove_suffix(2);
  double v = 0;
  const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
  if (ec != std::errc() || end != value.data() + value.size()) throw Error(fmt::format("not an SVG length in points: '{}'", value));
  return v;
}

std::string_view root_tag(std::string_view svg) {
  const auto start = svg.find("<svg");
  const auto end = start == std::string_view::npos ? start : svg.find('>', start);
  if (end == std::string_view::npos) throw Error("not an SVG picture: no <svg> element");
  return svg.substr(start, end - start);
}

// `svg` (ids prefixed) as a nested <svg> placed at (x, y) of the figure:
// its root's width and height in points become user units, which the
// figure's viewBox maps to points.
std::string placed(std::string_view svg, SvgSize size, std::string_view prefix, double x, double y) {
  std::string body = inline_svg(svg, prefix);
  const auto tag_end = body.find('>');
  std::string tag = body.substr(0, tag_end);
  for (const char* name : {"width", "height"}) {
    std::size_t at = 0;
    const auto value = attribute(tag, name, &at);
    if (value.empty()) continue;
    tag.erase(at, value.size() + std::string_view(name).size() + 4);
  }
  tag.insert(4, fmt::format(" x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\"", x, y, size.width, size.height));
  return tag + body.substr(tag_end) + "\n";
}

}  // namespace

SvgSize svg_size(std::string_view svg) {
  const auto tag = root_tag(svg);
  const auto width = attribute(tag, "width"), height = attribute(tag, "height");
  if (width.empty() || height.empty()) throw Error("SVG picture without width and height");
  return {points(width), points(height)};
}

std::string svg_figure(std::string_view head, const std::vector<std::string>& panels, double max_width) {
  const SvgSize head_size = svg_size(head);
  std::string parts = placed(head, head_size, "head_", 0, 0);
  // Rows of panels: left to right, a new row when the next would overflow.
  double x = 0, y = head_size.height + gap / 2, row_height = 0, width = head_size.width;
  for (std::size_t k = 0; k < panels.size(); ++k) {
    const SvgSize s = svg_size(panels[k]);
    if (x > 0 && x + s.width > max_width) {
      x = 0;
      y += row_height + gap;
      row_height = 0;
    }
    parts += placed(panels[k], s, fmt::format("panel{}_", k), x, y);
    width = std::max(width, x + s.width);
    row_height = std::max(row_height, s.height);
    x += s.width + gap;
  }
  const double height = y + row_height;
  return fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"{0:.2f}pt\" height=\"{1:.2f}pt\" "
      "viewBox=\"0 0 {0:.2f} {1:.2f}\">\n{2}</svg>\n",
      width, height, parts);
}

}  // namespace dartcheck::reports
