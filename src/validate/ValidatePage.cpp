// validate --figures' index.html: real HTML (tables as <table>, figures as <img> of the SVGs),
// checked in headless Chromium by tests/html/validate_page.sh.
#include <fmt/format.h>

#include "src/validate/Validate.h"

namespace hemirad {

namespace {

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s)
    out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : c == '"' ? "&quot;" : std::string(1, c);
  return out;
}

// The first row is the header.
std::string table(const std::string& id, const std::vector<std::vector<std::string>>& rows) {
  std::string out = fmt::format("<table id=\"{}\">\n", id);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    out += r == 0 ? "<thead><tr>" : r == 1 ? "<tbody><tr>" : "<tr>";
    for (const std::string& cell : rows[r]) out += fmt::format("<{0}>{1}</{0}>", r ? "td" : "th", escape(cell));
    out += r == 0 ? "</tr></thead>\n" : "</tr>\n";
  }
  return out + (rows.size() > 1 ? "</tbody></table>\n" : "</table>\n");
}

std::string figure(const std::string& stem, const std::string& caption, const char* width = "100%") {
  return fmt::format(
      "<figure style=\"width:{2}\"><img src=\"{0}.svg\" alt=\"{1}\"><figcaption>{1} "
      "(<a href=\"{0}.pdf\">PDF</a>)</figcaption></figure>\n",
      stem, escape(caption), width);
}

std::vector<std::vector<std::string>> provenanceRows(const Provenance& p) {
  return {{"", "this run"},       {"hemirad", p.version},  {"git commit", p.gitHash}, {"command line", p.commandLine},
          {"backend", p.backend}, {"renderer", p.renderer}};
}

std::vector<std::vector<std::string>> formFactorRows(const Validation& v) {
  std::vector<std::vector<std::string>> rows = {{"from", "to", "shooters of its elements",
                                                 "reference F (exact, over those shooters)", "GPU F (same shooters)",
                                                 "relative difference"}};
  for (const ObjectFormFactor& f : v.objectFormFactors)
    rows.push_back({f.from, f.to, fmt::format("{} of {}", f.shooters, f.elements), fmt::format("{:.5g}", f.reference),
                    fmt::format("{:.5g}", f.gpu),
                    f.reference > 0 ? fmt::format("{:.3g}", (f.gpu - f.reference) / f.reference) : "-"});
  return rows;
}

}  // namespace

std::string validationPage(const std::string& title, const Scene& scene, const Atlas& atlas, const ValidateOptions& o,
                           const Validation& v, const Provenance& provenance) {
  const int low = o.levels.front(), high = o.levels.back();
  const glm::dvec3 shooter(atlas.positionArea[v.figureShooter]);
  const std::string object = scene.objects[size_t(scene.polygons()[atlas.polygonOf[v.figureShooter]].object)].name;
  std::string page = fmt::format(
      "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>hemirad validation: {0}</title>\n"
      "<style>body{{font-family:sans-serif;max-width:1100px;margin:2em auto}}img{{width:100%}}"
      "figure{{display:inline-block;margin:0.5em;vertical-align:top}}figcaption{{font-size:85%}}"
      "table{{border-collapse:collapse;font-size:85%;margin:1em 0}}td,th{{border:1px solid #ccc;padding:3px 6px}}"
      "th{{background:#f3f3f3}}</style></head><body>\n<h1>hemirad validation: {0}</h1>\n"
      "<p>{1} elements, {2} shooters; exact reference: CGAL visibility between element centres and "
      "contour-integral form factors. Data: <a href=\"levels.csv\">levels.csv</a>.</p>\n<h2>Run</h2>\n",
      escape(title), v.elements, v.shooters);
  page += table("provenance", provenanceRows(provenance));
  page += "<h2>Against the item-mesh level L</h2>\n" + table("levels", levelRows(v));
  page += figure("agreement_vs_level", "visibility agreement against L", "47%") +
          figure("disagreement_vs_level", "visibility disagreements against L", "47%") +
          figure("ff_error_vs_level", "form-factor error against L", "47%");
  page += fmt::format(
      "<h2>Per texel, one shooter</h2>\n<p>The shooter element at ({:.4g}, {:.4g}, {:.4g}) on {}: the one whose "
      "visibility errors misplace the most form factor at L = {} ({}).</p>\n",
      shooter.x, shooter.y, shooter.z, escape(object), low, escape(configName(v.levels.front())));
  page += fmt::format(
      "<figure style=\"width:96%\"><img src=\"view_visibility_L{0}.png\" alt=\"camera view, L = {0}\" "
      "style=\"width:49%\"> <img src=\"view_visibility_L{1}.png\" alt=\"camera view, L = {1}\" "
      "style=\"width:49%\">"
      "<figcaption>Camera view of the visibility classes at L = {0} and L = {1}: light grey visible "
      "in both, dark grey hidden in both, orange false visible (the GPU sees, the exact test does "
      "not), blue false hidden, green the shooter, black not facing.</figcaption></figure>\n",
      low, high);
  page += figure(fmt::format("atlas_visibility_L{}", low), fmt::format("visibility classes on the atlas, L = {}", low),
                 "47%") +
          figure(fmt::format("atlas_visibility_L{}", high),
                 fmt::format("visibility classes on the atlas, L = {}", high), "47%") +
          figure(fmt::format("atlas_ff_error_L{}", high),
                 fmt::format("relative form-factor error on the atlas, L = {} (log colour scale; black: no exact "
                             "value)",
                             high),
                 "62%");
  page += "<h2>Object to object form factors</h2>\n" + table("form_factors", formFactorRows(v));
  return page + "</body></html>\n";
}

}  // namespace hemirad
