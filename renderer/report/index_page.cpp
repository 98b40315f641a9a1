// Writing the report's index page (index_page.h).
#include "renderer/report/index_page.h"

#include "materials/core/text.h"
#include "renderer/report/html_text.h"
#include "renderer/report/site_layout.h"

#include <algorithm>
#include <map>
#include <sstream>

namespace glossy::report {

namespace {

// The figure columns of a model's group, in order.
struct Column {
  const char* heading;
  const char* title;  // the header's tooltip
};
constexpr Column kColumns[] = {
    {"rRMSE", "relative RMSE against the measured panel over the object's pixels, render noise taken out (lower is closer)"},
    {"lum.", "luminance ratio model / measured over the object's pixels (1 is equal)"},
    {"\xEA\x9F\xBBLIP", "mean HDR-\xEA\x9F\xBBLIP over the object's pixels (lower is closer)"},
    {"E1", "the fit's E1 against the measured table"},
    {"E2", "the fit's E2 against the measured table"},
    {"closest", "this model is the closest to the measured panel (or ties for it)"},
};
constexpr int kFixedColumns = 3;  // thumbnail, material, verdict

std::string intervalTitle(const Figure& f) {
  if (!f.lo || !f.hi) return "";
  return " title=\"95 %: " + shortNumber(f.lo) + " to " + shortNumber(f.hi) + "\"";
}

std::string numberCell(const std::optional<double>& v, const std::string& extra, bool first, bool best) {
  std::string cls = first ? "group-start" : "";
  if (best && v) cls += cls.empty() ? "best" : " best";
  return "<td" + (cls.empty() ? std::string() : " class=\"" + cls + "\"") + " data-value=\"" + sortValue(v) + "\"" + extra + ">" +
         shortNumber(v) + "</td>";
}

// The kind of measured data a sheet's glossy:measured names, without the file: "MERL (NBRDF
// reconstruction) ../merl/chrome.binary.xz" → "MERL (NBRDF reconstruction)". Results from reconstructions
// must say so, on the index too.
std::string sourceLabel(const std::string& measured) {
  const size_t space = measured.rfind(' ');
  if (space == std::string::npos) return measured.find('/') == std::string::npos ? measured : std::string();
  const std::string last = measured.substr(space + 1);
  return last.find('/') != std::string::npos || last.find('.') != std::string::npos ? measured.substr(0, space) : measured;
}

// What every sheet was made with (checkSameSettings made sure they agree): the figures and medians below
// compare like with like only under these.
std::string settingsParagraph(const std::vector<SheetRecord>& sheets) {
  if (sheets.empty()) return "";
  std::map<std::string, std::string> value;
  for (const SheetSetting& s : sheets.front().settings) value[s.key] = s.value;
  const bool adaptive = value["time"] != "0" || value["targetError"] != "0";
  std::string text;
  for (const SheetSetting& s : sheets.front().settings) {
    if (s.key == "format" || ((s.key == "time" || s.key == "targetError") && s.value == "0")) continue;
    const std::string label = s.key == "spp" && adaptive ? "samples per pixel at most" : s.label;
    text += (text.empty() ? "" : "; ") + escapeHtml(label) + " " + escapeHtml(s.value);
  }
  return "<p class=\"settings\">Every sheet made with: " + text + ".</p>\n";
}

// How many materials' measured data came from each kind of source ("none" for those without).
std::string sourcesParagraph(const std::vector<SheetRecord>& sheets) {
  std::map<std::string, int> sources;
  for (const SheetRecord& s : sheets) {
    const PanelRecord* m = s.measuredPanel();
    ++sources[!m || m->empty || s.measured.empty() ? std::string("none") : sourceLabel(s.measured)];
  }
  return "<p>Measured data: " + joined(sources, "; ", [](const auto& source) {
    return escapeHtml(source.first) + " (" + std::to_string(source.second) + (source.second == 1 ? " material)" : " materials)");
  }) + ".</p>\n";
}

// Per model: how often it is the closest, and the medians of its figures over the materials.
void summaryTable(std::ostringstream& h, const std::vector<ModelSummary>& summary) {
  h << "<h2 id=\"summary-heading\">Per model</h2>\n<div class=\"table-wrap\">\n<table id=\"summary\" class=\"summary\" "
       "aria-labelledby=\"summary-heading\">\n<thead><tr><th class=\"text\" scope=\"col\">Model</th>"
       "<th scope=\"col\" title=\"materials where this model alone is the closest\">closest</th>"
       "<th scope=\"col\" title=\"materials where it ties for the closest with other models\">ties</th>"
       "<th scope=\"col\" title=\"materials with a relative RMSE for this model\">compared</th>"
       "<th scope=\"col\">median rRMSE</th><th scope=\"col\">median lum.</th><th scope=\"col\">median \xEA\x9F\xBBLIP</th>"
       "<th scope=\"col\">median E1</th><th scope=\"col\">median E2</th></tr></thead>\n<tbody>\n";
  for (const ModelSummary& m : summary)
    h << "<tr data-layer=\"" << escapeHtml(m.layer) << "\"><td class=\"model\"" << styleColour(m.colour) << ">" << escapeHtml(m.label)
      << "</td><td>" << m.closest << "</td><td>" << m.ties << "</td><td>" << m.compared << "</td><td>" << shortNumber(m.medianRelativeRmse)
      << "</td><td>" << shortNumber(m.medianLuminanceRatio) << "</td><td>" << shortNumber(m.medianFlip) << "</td><td>"
      << shortNumber(m.medianE1) << "</td><td>" << shortNumber(m.medianE2) << "</td></tr>\n";
  h << "</tbody>\n</table>\n</div>\n";
}

// The materials table's heading, filter and column headers: the fixed columns, then a group per model.
void materialsTableHead(std::ostringstream& h, size_t materials, const std::vector<std::string>& layers, const std::vector<ModelSummary>& summary) {
  h << "<h2 id=\"materials-heading\">Materials</h2>\n<div class=\"controls\"><label for=\"filter\">Filter</label>"
       "<input id=\"filter\" type=\"search\" placeholder=\"material name or verdict\" autocomplete=\"off\">"
       "<span id=\"shown\" class=\"muted\" aria-live=\"polite\">"
    << materials << " materials</span></div>\n"
    << "<noscript><p>Sorting, filtering and the compare views need JavaScript; the tables and images are all here without it.</p></noscript>\n"
    << "<div class=\"table-wrap\">\n<table id=\"materials\" aria-labelledby=\"materials-heading\">\n<thead>\n<tr>"
    << "<th rowspan=\"2\" scope=\"col\">Preview</th>"
    << "<th rowspan=\"2\" scope=\"col\" class=\"name\" data-col=\"1\" data-type=\"text\"><button class=\"sort\" type=\"button\">Material</button></th>"
    << "<th rowspan=\"2\" scope=\"col\" class=\"text\" data-col=\"2\" data-type=\"text\"><button class=\"sort\" type=\"button\">Verdict</button></th>";
  for (const ModelSummary& m : summary)
    h << "<th colspan=\"" << std::size(kColumns) << "\" scope=\"colgroup\" class=\"group\"" << styleColour(m.colour) << ">"
      << escapeHtml(m.label) << "</th>";
  h << "</tr>\n<tr>";
  for (size_t k = 0; k < layers.size(); ++k)
    for (size_t c = 0; c < std::size(kColumns); ++c)
      h << "<th scope=\"col\"" << (c == 0 ? " class=\"group-start\"" : "") << " data-col=\"" << kFixedColumns + k * std::size(kColumns) + c
        << "\" data-type=\"number\" data-layer=\"" << escapeHtml(layers[k]) << "\" title=\"" << kColumns[c].title
        << "\"><button class=\"sort\" type=\"button\" aria-label=\"" << escapeHtml(summary[k].label) << " " << kColumns[c].heading
        << "\">" << kColumns[c].heading << "</button></th>";
  h << "</tr>\n</thead>\n<tbody class=\"rows\">\n";
}

// A material's row: its thumbnail, name, verdict and warnings, then each model's figures ("–" where the
// sheet has no such panel).
void materialRow(std::ostringstream& h, const SheetRecord& s, const std::vector<std::string>& layers) {
  const std::string folder = layout::materialFolder(s.name) + "/";
  const std::string page = layout::materialPage(s.name);
  h << "<tr data-name=\"" << escapeHtml(s.name) << "\" data-verdict=\"" << escapeHtml(s.verdict) << "\">";
  if (const PanelRecord* t = thumbnailPanel(s))
    h << "<td class=\"thumb\"><a href=\"" << page << "\" tabindex=\"-1\"><img src=\"" << folder << layout::panelImage(t->layer)
      << "\" width=\"48\" height=\"48\" alt=\"" << escapeHtml(s.name + ": " + t->label) << "\"></a></td>";
  else
    h << "<td class=\"thumb\">–</td>";
  h << "<td class=\"name\" data-value=\"" << escapeHtml(s.name) << "\" title=\"" << escapeHtml(withoutFolders(s.measured)) << "\"><a href=\"" << page << "\">" << escapeHtml(s.name) << "</a></td>";
  h << "<td class=\"text verdict\">" << escapeHtml(s.verdict.empty() ? "–" : s.verdict);
  for (const std::string& w : s.warnings) h << "<br><span class=\"warning\">warning: " << escapeHtml(w) << "</span>";
  h << "</td>";
  const std::vector<std::string> closest = s.closestLayers();
  for (const std::string& layer : layers) {
    const PanelRecord* p = s.panel(layer);
    if (!p) {
      for (size_t c = 0; c < std::size(kColumns); ++c) h << "<td" << (c == 0 ? " class=\"group-start\"" : "") << " data-value=\"\">–</td>";
      continue;
    }
    const bool best = std::find(closest.begin(), closest.end(), layer) != closest.end();
    h << numberCell(p->relativeRmse.value, intervalTitle(p->relativeRmse), true, best)
      << numberCell(p->luminanceRatio.value, intervalTitle(p->luminanceRatio), false, false)
      << numberCell(p->flip.value, intervalTitle(p->flip), false, false) << numberCell(p->e1, "", false, false)
      << numberCell(p->e2, "", false, false);
    // 1 closest, 0.5 tie, 0 not; absent when the sheet has no verdict at all.
    if (closest.empty())
      h << "<td data-value=\"\"></td>";
    else if (best)
      h << "<td class=\"closest-mark\" data-value=\"" << (closest.size() == 1 ? "1" : "0.5") << "\">"
        << (closest.size() == 1 ? "closest" : "tie") << "</td>";
    else
      h << "<td data-value=\"0\"></td>";
  }
  h << "</tr>\n";
}

}  // namespace

const PanelRecord* thumbnailPanel(const SheetRecord& sheet) {
  const PanelRecord* m = sheet.measuredPanel();
  if (m && !m->empty) return m;
  for (const PanelRecord& p : sheet.panels)
    if (!p.empty) return &p;
  return nullptr;
}

std::string indexPage(const std::vector<SheetRecord>& sheets) {
  const std::vector<std::string> layers = modelLayers(sheets);
  const std::vector<ModelSummary> summary = summarizeModels(sheets);
  std::ostringstream h;
  h << pageStart(formatted("glossy report: %zu materials", sheets.size()), "");
  h << "<header class=\"site\">\n<h1>Analytic BRDF models against measured data</h1>\n"
    << "<p>Each material's sheet renders the measured BRDF and the fits of the analytic models (Löw et al. 2012) in the same scene; "
       "the figures say how far each model's image is from the measured one over the object's pixels. "
    << sheets.size() << " materials.</p>\n";
  h << sourcesParagraph(sheets) << settingsParagraph(sheets) << "</header>\n<main>\n";
  summaryTable(h, summary);
  materialsTableHead(h, sheets.size(), layers, summary);
  for (const SheetRecord& s : sheets) materialRow(h, s, layers);
  h << "</tbody>\n</table>\n</div>\n";
  h << "<p class=\"muted\">Click a column's header to sort by it (again to reverse); materials without the figure stay last. "
       "Hover a figure for its 95 % interval. rRMSE: relative RMSE with the render noise taken out; lum.: luminance ratio; "
       "\xEA\x9F\xBBLIP: mean HDR-\xEA\x9F\xBBLIP; E1, E2: the fit's error against the measured table (docs/fitting.md).</p>\n";
  h << "</main>\n";
  h << pageEnd("Made by <code>glossy report</code> from the sheets of <code>glossy sheets</code>.");
  return h.str();
}

}  // namespace glossy::report
