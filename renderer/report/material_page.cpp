// Writing a material's page (material_page.h).
#include "renderer/report/material_page.h"

#include "materials/core/text.h"
#include "renderer/report/html_text.h"
#include "renderer/report/site_layout.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

namespace glossy::report {

namespace {

constexpr const char* kRoot = "../../";

std::string withInterval(const Figure& f) {
  std::string s = shortNumber(f.value);
  if (f.value && f.lo && f.hi) s += " <span class=\"muted\">[" + shortNumber(f.lo) + ", " + shortNumber(f.hi) + "]</span>";
  return s;
}

// An image's figures as the errors table's cells: rel. RMSE, noisy rRMSE, luminance ratio, ꟻLIP, ΔE_ITP, SSIM.
std::string figureCells(const ImageFigures& f) {
  return "<td>" + withInterval(f.relativeRmse) + "</td><td>" + shortNumber(f.relativeRmseNoisy) + "</td><td>" +
         withInterval(f.luminanceRatio) + "</td><td>" + withInterval(f.flip) + "</td><td>" + withInterval(f.deltaEItp) + "</td><td>" +
         withInterval(f.ssim) + "</td>";
}

void metaRow(std::ostringstream& h, const char* name, const std::string& value) {
  if (!value.empty()) h << "<dt>" << name << "</dt><dd>" << escapeHtml(value) << "</dd>\n";
}

// A file the sheet names by its path on the machine that rendered it: its name only, so a published site
// does not carry the renderer's folders (the sheet's EXR keeps the path).
void fileRow(std::ostringstream& h, const char* name, const std::string& path) {
  if (path.empty()) return;
  const std::string file = std::filesystem::path(path).filename().string();
  h << "<dt>" << name << "</dt><dd>" << escapeHtml(file.empty() ? path : file) << "</dd>\n";
}

// The page's header: links to the index and the neighbouring materials, the name, verdict, warnings and
// what the sheet was made from.
void pageHeader(std::ostringstream& h, const SheetRecord& s, const SheetRecord* previous, const SheetRecord* next) {
  h << "<header class=\"site\">\n<nav class=\"crumbs\" aria-label=\"pages\"><a href=\"" << kRoot << layout::kIndex << "\">All materials</a>";
  if (previous)
    h << "<a href=\"" << kRoot << layout::materialPage(previous->name) << "\" rel=\"prev\">← " << escapeHtml(previous->name) << "</a>";
  if (next) h << "<a href=\"" << kRoot << layout::materialPage(next->name) << "\" rel=\"next\">" << escapeHtml(next->name) << " →</a>";
  h << "</nav>\n<h1>" << escapeHtml(s.name) << "</h1>\n<p class=\"verdict\">" << escapeHtml(s.verdict.empty() ? "no verdict" : s.verdict)
    << "</p>\n";
  for (const std::string& w : s.warnings) h << "<p class=\"warning\">Warning: " << escapeHtml(w) << "</p>\n";
  h << "<dl class=\"meta\">\n";
  metaRow(h, "measured data", withoutFolders(s.measured));
  fileRow(h, "material file", s.materialFile);
  fileRow(h, "scene", s.scene);
  metaRow(h, "lighting", s.env);
  metaRow(h, "samples per pixel", s.spp);
  metaRow(h, "PNG exposure", formatted("%+g stops", s.pngExposure));
  h << "</dl>\n</header>\n";
}

// The sheet as drawn: its panels, each in its box (the compare view's images), over the rest of it.
void sheetSection(std::ostringstream& h, const SheetRecord& s) {
  h << "<section aria-labelledby=\"sheet-heading\">\n<h2 id=\"sheet-heading\">Sheet</h2>\n<figure class=\"sheet\" style=\"max-width: " << s.imageWidth << "px\">"
    << "<div class=\"sheet-panels\" style=\"aspect-ratio: " << s.imageWidth << " / " << s.panelsBottom << "\">";
  const double w = s.imageWidth, b = s.panelsBottom;
  for (const PanelRecord& p : s.panels)
    h << "<img src=\"" << layout::panelImage(p.layer) << "\" alt=\"" << escapeHtml(p.label) << "\" width=\"" << p.width << "\" height=\""
      << p.height << "\" style=\"" << formatted("left:%.4f%%;top:%.4f%%;width:%.4f%%;height:%.4f%%", 100 * p.x / w, 100 * p.y / b, 100 * p.width / w,
                                                100 * p.height / b)
      << "\">";
  h << "</div>";
  if (s.panelsBottom < s.pngHeight)
    h << "<img class=\"sheet-lower\" src=\"" << layout::sheetLowerImage() << "\" width=\"" << s.imageWidth << "\" height=\""
      << s.pngHeight - s.panelsBottom << "\" alt=\"" << escapeHtml("each panel's label and figures, and the error maps against the measured panel")
      << "\">";
  h << "\n<figcaption>";
  for (size_t k = 0; k < s.panels.size(); ++k) h << (k ? " | " : "") << escapeHtml(s.panels[k].label);
  h << ". Under the panels: each one's label and figures, and a row of error maps against the measured panel with its legend."
       "</figcaption></figure>\n</section>\n";
}

// The compare view: a model's panel, with the measured panel in its place on demand.
void compareSection(std::ostringstream& h, const SheetRecord& s) {
  const PanelRecord* measured = s.measuredPanel();
  const bool hasMeasured = measured && !measured->empty;
  const PanelRecord* first = nullptr;
  for (const PanelRecord& p : s.panels)
    if (!p.isMeasured() && !p.empty) {
      first = &p;
      break;
    }
  h << "<section aria-labelledby=\"compare-heading\">\n<h2 id=\"compare-heading\">Compare</h2>\n";
  if (!first && !hasMeasured) {
    h << "<p>Every panel of this sheet is empty.</p>\n";
  } else {
    const PanelRecord* shown = first ? first : measured;
    h << "<div class=\"compare\">\n<div class=\"compare-view\"><img class=\"compare-image\" src=\"" << layout::panelImage(shown->layer)
      << "\" width=\"" << shown->width << "\" height=\"" << shown->height << "\" alt=\"" << escapeHtml(shown->label) << " panel\"";
    if (hasMeasured)
      h << " data-measured-src=\"" << layout::panelImage(measured->layer) << "\" data-measured-label=\"" << escapeHtml(measured->label) << "\"";
    h << "><p class=\"compare-label\" aria-live=\"polite\">Showing: " << escapeHtml(shown->label) << "</p></div>\n"
      << "<div class=\"compare-controls\">\n<div class=\"models\" role=\"group\" aria-label=\"model panel\">";
    for (const PanelRecord& p : s.panels) {
      if (p.isMeasured()) continue;
      h << "<button type=\"button\" class=\"model\"" << styleColour(p.colour) << " data-layer=\"" << escapeHtml(p.layer) << "\" data-label=\""
        << escapeHtml(p.label) << "\"";
      if (p.empty)
        h << " disabled title=\"" << escapeHtml(p.note.empty() ? "empty panel" : p.note) << "\"";
      else
        h << " data-src=\"" << layout::panelImage(p.layer) << "\" aria-pressed=\"" << (&p == first ? "true" : "false") << "\"";
      h << ">" << escapeHtml(p.label) << "</button>";
    }
    h << "</div>\n";
    if (hasMeasured && first)
      h << "<button type=\"button\" class=\"toggle\" aria-pressed=\"false\">Show measured</button>\n"
           "<p class=\"muted\">Choose a model, then press <em>Show measured</em> or point at the image to see the measured panel in "
           "its place, at the same exposure.</p>\n";
    else
      h << "<p class=\"muted\">" << (hasMeasured ? "No model panel to compare." : "No measured panel to compare against.") << "</p>\n";
    h << "</div>\n</div>\n";
  }
  h << "</section>\n";
}

// Each panel's figures against the measured panel, and the noise floor's.
void errorsSection(std::ostringstream& h, const SheetRecord& s) {
  h << "<section aria-labelledby=\"errors-heading\">\n<h2 id=\"errors-heading\">Errors against the measured panel</h2>\n"
    << "<div class=\"table-wrap\"><table class=\"errors\">\n<thead><tr><th class=\"text\" scope=\"col\">Panel</th>"
       "<th scope=\"col\">rel. RMSE [95 %]</th><th scope=\"col\">noisy rRMSE</th><th scope=\"col\">luminance ratio [95 %]</th>"
       "<th scope=\"col\">\xEA\x9F\xBBLIP [95 %]</th><th scope=\"col\">\xCE\x94" "E<sub>ITP</sub> [95 %]</th>"
       "<th scope=\"col\">SSIM [95 %]</th><th scope=\"col\">E1</th><th scope=\"col\">E2</th><th class=\"text\" scope=\"col\">Note</th></tr></thead>\n<tbody>\n";
  const std::vector<std::string> closest = s.closestLayers();
  for (const PanelRecord& p : s.panels) {
    // The measured panel's note says where its data came from: without the renderer's folders.
    const std::string said = p.isMeasured() ? withoutFolders(p.note) : p.note;
    std::string note = p.empty ? (said.empty() ? std::string("empty") : "empty: " + said) : said;
    if (!p.noiseFree.empty() && p.noiseFree != "yes") note += (note.empty() ? "" : "; ") + p.noiseFree;
    const bool best = std::find(closest.begin(), closest.end(), p.layer) != closest.end();
    h << "<tr><th class=\"text\" scope=\"row\">" << escapeHtml(p.label) << (best ? " <span class=\"closest-mark\">(closest)</span>" : "")
      << "</th>" << figureCells(p) << "<td>" << shortNumber(p.e1) << "</td><td>" << shortNumber(p.e2) << "</td><td class=\"note\">"
      << escapeHtml(note) << "</td></tr>\n";
  }
  if (const auto& f = s.noiseFloor)
    h << "<tr class=\"noise-floor\"><th class=\"text\" scope=\"row\">noise floor</th>" << figureCells(*f)
      << "<td></td><td></td><td class=\"note\">the measured panel against an independent render of itself: what noise alone shows</td></tr>\n";
  h << "</tbody>\n</table></div>\n<p class=\"muted\">Over the object's pixels. rel. RMSE has the render noise taken out (from "
       "independent replicates), the noisy one keeps it; \xEA\x9F\xBBLIP includes the noise, which raises it, and its interval is the "
       "noise's spread";
  if (s.flipNoiseFloor) h << " (noise alone gives " << shortNumber(s.flipNoiseFloor) << ": the measured panel against itself)";
  h << "; \xCE\x94" "E<sub>ITP</sub> and SSIM compare the panels as the PNG shows them at exposure 0 and are treated alike (noise "
       "raises \xCE\x94" "E<sub>ITP</sub> and lowers SSIM); E1 and E2 score the fit against the measured table itself, not the image.</p>\n"
       "</section>\n";
}

// Each model panel's fit and its parameters.
void parametersSection(std::ostringstream& h, const SheetRecord& s) {
  h << "<section aria-labelledby=\"params-heading\">\n<h2 id=\"params-heading\">Fit parameters</h2>\n<div class=\"table-wrap\"><table>\n"
       "<thead><tr><th class=\"text\" scope=\"col\">Panel</th><th class=\"text\" scope=\"col\">Fit</th><th class=\"text\" scope=\"col\">Parameters</th></tr></thead>\n<tbody>\n";
  for (const PanelRecord& p : s.panels) {
    if (p.isMeasured()) continue;
    h << "<tr><th class=\"text\" scope=\"row\">" << escapeHtml(p.label) << "</th><td class=\"text\"><code>" << escapeHtml(p.fit.empty() ? "–" : p.fit)
      << "</code></td><td class=\"text params\">" << escapeHtml(p.params.empty() ? (p.empty ? "no fit" : "–") : p.params) << "</td></tr>\n";
  }
  h << "</tbody>\n</table></div>\n</section>\n";
}

// The material's plots from glossy plot, captioned, with links to their SVG and CSV where the site has them.
void plotsSection(std::ostringstream& h, const PlotIndex* plots) {
  h << "<section aria-labelledby=\"plots-heading\">\n<h2 id=\"plots-heading\">Plots</h2>\n";
  if (!plots || plots->figures.empty()) {
    h << "<p class=\"muted\">No plots for this material (<code>glossy plot</code> makes them).</p>\n";
  } else {
    if (!plots->measured.empty() || !plots->channel.empty())
      h << "<p class=\"muted\">" << escapeHtml(withoutFolders(plots->measured)) << (plots->channel.empty() ? "" : "; channel: " + escapeHtml(plots->channel))
        << "</p>\n";
    h << "<div class=\"plots\">\n";
    for (const PlotFigure& f : plots->figures) {
      const std::string image = layout::plotFile(f.shown);
      h << "<figure><h3>" << escapeHtml(f.title) << "</h3><img src=\"" << image << "\" alt=\"" << escapeHtml(f.title) << "\">";
      h << "<figcaption>" << escapeHtml(f.caption);
      std::string links;
      if (!f.svg.empty()) links += "<a href=\"" + layout::plotFile(f.svg) + "\">SVG</a>";
      if (!f.csv.empty()) links += std::string(links.empty() ? "" : " · ") + "<a href=\"" + layout::plotFile(f.csv) + "\">data (CSV)</a>";
      if (!links.empty()) h << (f.caption.empty() ? "" : " ") << "<span class=\"links\">" << links << "</span>";
      h << "</figcaption></figure>\n";
    }
    h << "</div>\n";
  }
  h << "</section>\n";
}

}  // namespace

std::string materialPage(const SheetRecord& s, const PlotIndex* plots, const SheetRecord* previous, const SheetRecord* next) {
  std::ostringstream h;
  h << pageStart(s.name + " · glossy report", kRoot);
  pageHeader(h, s, previous, next);
  h << "<main>\n";
  sheetSection(h, s);
  compareSection(h, s);
  errorsSection(h, s);
  parametersSection(h, s);
  plotsSection(h, plots);
  h << "</main>\n";
  h << pageEnd("Made by <code>glossy report</code> from <code>" + escapeHtml(s.exr.filename().string()) + "</code>.");
  return h.str();
}

}  // namespace glossy::report
