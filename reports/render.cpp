#include "reports/render.hpp"

#include <graphviz/gvc.h>

#include <cstdio>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"

#if defined(__SANITIZE_ADDRESS__)
// Graphviz's plugins and fontconfig keep process-lifetime caches that
// LeakSanitizer reports at exit; the objects this file allocates are all
// freed (gvFreeRenderData, gvFreeLayout, agclose; the one context at exit).
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libgvc.so\nleak:libcgraph.so\nleak:libgvplugin\nleak:libfontconfig.so\nleak:libpango\nleak:libcairo.so\nleak:libglib\n";
}
// The suppressions' statistics go to stderr at exit; commands whose stderr
// is tested (-q prints nothing) must print the same under the sanitizers.
extern "C" const char* __lsan_default_options() { return "print_suppressions=0"; }
#endif

namespace dartcheck::reports {
namespace {

// Graphviz reports through a global error hook; keep the last message.
std::string& last_error() {
  static std::string message;
  return message;
}

int keep_error(char* text) {
  last_error() += text;
  return 0;
}

std::string take_error(std::string_view what) {
  std::string m = std::exchange(last_error(), {});
  while (!m.empty() && (m.back() == '\n' || m.back() == ' ')) m.pop_back();
  return std::string(what) + (m.empty() ? "" : ": " + m);
}

}  // namespace

namespace {

// Lays `dot` out with `engine` (or the graph's own `layout` attribute) and
// calls `use` on the laid-out graph, under the one lock libgvc needs.
template <class Use>
void with_layout(std::string_view dot, std::string_view engine, Use use) {
  // libgvc keeps global state (error hook, plugin registry): one caller at
  // a time.
  static std::mutex lock;
  const std::lock_guard guard(lock);
  agseterrf(keep_error);
  agseterr(AGWARN);
  last_error().clear();
  // One context for the process: Graphviz 2.43's pango plugin caches the
  // last font name across contexts, so freeing a context and making a new
  // one reads freed memory (AddressSanitizer shows it).
  static const std::unique_ptr<GVC_t, int (*)(GVC_t*)> gvc(gvContext(), gvFreeContext);
  if (!gvc) throw Error("Graphviz: no context");
  const std::string text(dot);
  std::unique_ptr<Agraph_t, int (*)(Agraph_t*)> g(agmemread(text.c_str()), agclose);
  if (!g) throw Error(take_error("Graphviz cannot read the DOT text"));
  const std::string eng(engine);
  if (gvLayout(gvc.get(), g.get(), eng.c_str()) != 0) throw Error(take_error("Graphviz layout '" + eng + "' failed"));
  try {
    use(gvc.get(), g.get());
  } catch (...) {
    gvFreeLayout(gvc.get(), g.get());
    throw;
  }
  gvFreeLayout(gvc.get(), g.get());
}

// Renders the laid-out `g` in `format`.
std::string render_data(GVC_t* gvc, Agraph_t* g, const std::string& format) {
  char* data = nullptr;
  unsigned int length = 0;
  const int rc = gvRenderData(gvc, g, format.c_str(), &data, &length);
  std::string out = rc == 0 && data ? std::string(data, length) : std::string();
  if (data) gvFreeRenderData(data);
  if (rc != 0) throw Error(take_error("Graphviz cannot render format '" + format + "'"));
  return out;
}

}  // namespace

std::string render(std::string_view dot, std::string_view format, std::string_view engine) {
  std::string out;
  with_layout(dot, engine, [&](GVC_t* gvc, Agraph_t* g) { out = render_data(gvc, g, std::string(format)); });
  return out;
}

std::vector<NodePosition> node_positions(std::string_view dot, std::string_view engine) {
  std::vector<NodePosition> out;
  with_layout(dot, engine, [&](GVC_t* gvc, Agraph_t* g) {
    render_data(gvc, g, "dot");  // attaches each node's pos="x,y[,z]" to the graph
    for (Agnode_t* n = agfstnode(g); n; n = agnxtnode(g, n)) {
      NodePosition p{agnameof(n), {0, 0, 0}};
      char pos_name[] = "pos", width_name[] = "width", height_name[] = "height";
      const char* pos = agget(n, pos_name);
      if (!pos || std::sscanf(pos, "%lf,%lf,%lf", &p.at[0], &p.at[1], &p.at[2]) < 2)
        throw Error(fmt::format("Graphviz gave node {} no position", p.name));
      const char *width = agget(n, width_name), *height = agget(n, height_name);
      if (width) std::sscanf(width, "%lf", &p.width);
      if (height) std::sscanf(height, "%lf", &p.height);
      out.push_back(std::move(p));
    }
  });
  return out;
}

std::string format_of(std::string_view file) {
  const auto dot = file.rfind('.');
  const std::string ext = dot == std::string_view::npos ? "" : std::string(file.substr(dot + 1));
  if (ext == "svg" || ext == "png" || ext == "dot" || ext == "pdf") return ext;
  if (ext == "gv") return "dot";
  throw ValueError("'" + std::string(file) + "': expected a file name ending in .svg, .png, .pdf, .dot or .gv");
}

std::size_t write_picture(std::string_view dot, const std::string& file, std::string_view engine) {
  std::string format;
  try {
    format = format_of(file);
  } catch (const ValueError& e) {
    throw UsageError(fmt::format("-o: {}", e.what()));
  }
  const std::string data = format == "dot" ? std::string(dot) : render(dot, format, engine);
  write_file(file, data);
  return data.size();
}

}  // namespace dartcheck::reports
