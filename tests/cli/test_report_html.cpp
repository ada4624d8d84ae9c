// `dartcheck report`: the page is well-formed (parsed with pugixml), has a
// section and a picture for every rule of the catalog, every in-page link
// lands on an element, every rule the fuzzer confirms has its
// counterexample drawn; and headless Chromium renders it to a screenshot
// that is not blank (skipped when chromium is not installed).
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <png.h>
#include <pugixml.hpp>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>

#include "checkers/rule_conditions.hpp"
#include "cli/commands.hpp"
#include "io/catalog.hpp"
#include "core/input_error.hpp"
#include "reports/html_page.hpp"

using namespace dartcheck;
namespace fs = std::filesystem;

namespace {

const std::string seed_catalog = std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/seed-operations.yaml";

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("dartcheck-{}-{}", name, ::getpid());
  fs::remove_all(dir);
  return dir;
}

// The report on the seed catalog with 3 s of fuzzing, written once.
const fs::path& fuzzed_report() {
  static const fs::path dir = [] {
    const fs::path d = fresh_dir("report");
    cli::ReportOptions o;
    o.catalog = seed_catalog;
    o.output = d.string();
    o.fuzz = "3s";
    o.seed = 1;
    EXPECT_EQ(cli::report(o), cli::ok);
    return d;
  }();
  return dir;
}

bool has_class(const pugi::xml_node& n, const char* cls) {
  const std::string c = n.attribute("class").value();
  return c == cls;
}

}  // namespace

TEST(ReportHtml, EveryRuleHasASectionAPictureAndResolvedLinks) {
  const fs::path index = fuzzed_report() / "index.html";
  pugi::xml_document doc;
  const auto parsed = doc.load_file(index.c_str());
  ASSERT_TRUE(parsed) << parsed.description() << " at byte " << parsed.offset;

  std::set<std::string> ids;
  for (const auto& x : doc.select_nodes("//*[@id]")) ids.insert(x.node().attribute("id").value());
  const Catalog catalog = read_catalog(seed_catalog);
  for (const auto& e : catalog.rules) {
    const std::string id = reports::html_id(e.rule.name());
    const auto h2 = doc.select_node(fmt::format("//h2[@id='{}']", id).c_str());
    ASSERT_TRUE(h2) << e.rule.name() << " has no section";
    // The rule's picture follows its heading: one SVG node per node of L and
    // R, and the two sides' frames.
    pugi::xml_node pic = h2.node().next_sibling();
    while (pic && !has_class(pic, "picture")) pic = pic.next_sibling();
    ASSERT_TRUE(pic) << e.rule.name() << " has no picture";
    std::size_t nodes = 0;
    for (const auto& n : pic.select_nodes(".//*[@class='node']/*[local-name()='title']"))
      nodes += !std::string_view(n.node().child_value()).ends_with("#frame");
    EXPECT_EQ(nodes, e.rule.left().node_count() + e.rule.right().node_count()) << e.rule.name();
  }
  std::size_t links = 0;
  for (const auto& a : doc.select_nodes("//a[@href]")) {
    const std::string href = a.node().attribute("href").value();
    if (href.starts_with("#")) {
      ++links;
      EXPECT_TRUE(ids.contains(href.substr(1))) << "dangling link " << href;
    } else {
      EXPECT_TRUE(fs::exists(fuzzed_report() / href)) << "missing file " << href;
    }
  }
  // Each rule's row links to its section; each failing cell to its condition.
  EXPECT_GE(links, catalog.rules.size() + 50);
}

// The screenshot's words, read from the DOM (issue 39): every rule's
// figure names each condition the checker says fails ("fails I(1): ..."),
// so a reader of the picture alone knows what is wrong.
TEST(ReportHtml, EveryFailingRulesFigureNamesItsConditions) {
  const fs::path index = fuzzed_report() / "index.html";
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file(index.c_str()));
  std::size_t named = 0;
  for (const auto& e : read_catalog(seed_catalog).rules) {
    const auto h2 = doc.select_node(fmt::format("//h2[@id='{}']", reports::html_id(e.rule.name())).c_str());
    ASSERT_TRUE(h2) << e.rule.name();
    pugi::xml_node pic = h2.node().next_sibling();
    while (pic && !has_class(pic, "picture")) pic = pic.next_sibling();
    ASSERT_TRUE(pic) << e.rule.name();
    std::string words;
    for (const auto& t : pic.select_nodes(".//*[local-name()='text']")) words += std::string(t.node().child_value()) + "\n";
    for (const auto& c : check_rule(e.rule, e.words).conditions)
      if (!c.holds) {
        EXPECT_NE(words.find("fails " + c.name()), std::string::npos) << e.rule.name() << "'s figure does not name " << c.name();
        ++named;
      }
  }
  EXPECT_GT(named, 40u);
}

// A rule the fuzzer confirms gets its counterexample drawn as three
// panels, with the files `dartcheck apply` replays beside it.
TEST(ReportHtml, ConfirmedFailuresAreDrawn) {
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file((fuzzed_report() / "index.html").c_str()));
  std::size_t confirmed = 0;
  for (const auto& row : doc.select_nodes("//table[@class='verdicts']/tr")) {
    const std::string fuzz = row.node().last_child().child_value();
    if (!fuzz.starts_with("confirmed")) continue;
    ++confirmed;
    const std::string rule = row.node().first_child().child("a").child_value();
    const std::string stem = [&] {
      std::string s = rule;
      std::replace(s.begin(), s.end(), '/', '.');
      return s;
    }();
    EXPECT_TRUE(fs::exists(fuzzed_report() / "counterexamples" / (stem + ".fuzz.svg"))) << rule;
    EXPECT_TRUE(fs::exists(fuzzed_report() / "counterexamples" / (stem + ".fuzz.host.yaml"))) << rule;
    pugi::xml_document svg;
    ASSERT_TRUE(svg.load_file((fuzzed_report() / "counterexamples" / (stem + ".fuzz.svg")).c_str())) << rule;
    std::size_t g = 0, h = 0;
    for (const auto& n : svg.select_nodes("//g[@class='node']/title")) {
      const std::string t = n.node().child_value();
      g += t.starts_with("G:");
      h += t.starts_with("H:");
    }
    EXPECT_GT(g, 0u) << rule;
    EXPECT_GT(h, 0u) << rule;
  }
  EXPECT_GE(confirmed, 40u);
}

// The events table of a rule (004 Sec. 3): the triangulation's face splits
// implicitly along position 1, conditionally (its L<0,1>(n0) is complete),
// as dartcheck events says and tests/events derives by hand.
TEST(ReportHtml, EachRuleHasItsEventsTable) {
  cli::ReportOptions o;
  o.catalog = std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/event-operations.yaml";
  o.output = fresh_dir("report-events").string();
  o.rule = "triangulate-face";
  ASSERT_EQ(cli::report(o), cli::ok);
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file((fs::path(o.output) / "index.html").c_str()));
  bool found = false;
  for (const auto& x : doc.select_nodes("//tr")) {
    std::string row;
    for (const auto& td : x.node().children("td")) row += std::string(td.text().get()) + "|";
    found = found || row == "<0,1>|L<0,1>(n0)|complete|conditional split along position 1 (letter 1); conditional modification|";
  }
  EXPECT_TRUE(found);
}

TEST(ReportHtml, BadInputIsAnErrorNotACrash) {
  cli::ReportOptions o;
  o.catalog = seed_catalog;
  o.output = fresh_dir("report-bad").string();
  o.fuzz = "soon";
  EXPECT_THROW(cli::report(o), InputError);
  o.fuzz.clear();
  o.rule = "no-such-rule";
  EXPECT_THROW(cli::report(o), InputError);
}

namespace {

// The fraction of pixels that differ from the top-left pixel (the page's
// background), and the number of distinct colors.
struct PngStats {
  std::size_t width = 0, height = 0, colors = 0;
  double ink = 0;
};

PngStats png_stats(const fs::path& file) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, file.c_str())) return {};
  image.format = PNG_FORMAT_RGB;
  std::vector<unsigned char> pixels(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr)) return {};
  PngStats s{image.width, image.height, 0, 0};
  std::set<std::uint32_t> colors;
  std::size_t ink = 0;
  for (std::size_t p = 0; p + 2 < pixels.size(); p += 3) {
    const std::uint32_t c = pixels[p] << 16 | pixels[p + 1] << 8 | pixels[p + 2];
    colors.insert(c);
    ink += pixels[p] != pixels[0] || pixels[p + 1] != pixels[1] || pixels[p + 2] != pixels[2];
  }
  s.colors = colors.size();
  s.ink = double(ink) / double(image.width * image.height);
  return s;
}

}  // namespace

TEST(ReportHtml, HeadlessChromiumRendersANonBlankPage) {
  if (std::system("command -v chromium > /dev/null 2>&1") != 0) GTEST_SKIP() << "chromium is not installed (scripts/install-deps.sh --tests installs it)";
  const fs::path shot = fresh_dir("report-shot").string() + ".png";
  // --no-sandbox: CI runs as root; the page needs no network.
  const std::string cmd = fmt::format(
      "timeout 120 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=1280,1600 --screenshot='{}' 'file://{}' "
      "> /dev/null 2>&1",
      shot.string(), fs::absolute(fuzzed_report() / "index.html").string());
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const PngStats s = png_stats(shot);
  EXPECT_EQ(s.width, 1280u);
  EXPECT_EQ(s.height, 1600u);
  // Text, the table's colored cells and the pictures: a blank or
  // error page has a handful of colors and almost no ink.
  EXPECT_GT(s.colors, 50u);
  EXPECT_GT(s.ink, 0.05);
  fs::remove(shot);
}
