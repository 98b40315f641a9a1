// Writing a study's top page (study_page.h).
#include "renderer/report/study_page.h"

#include "materials/core/text.h"
#include "renderer/report/html_text.h"
#include "renderer/report/markdown.h"
#include "renderer/report/site_layout.h"

#include <filesystem>
#include <map>
#include <set>
#include <sstream>

namespace glossy::report {

namespace {

std::string interval(const std::optional<double>& lo, const std::optional<double>& hi) {
  return lo && hi ? " title=\"95 %: " + shortNumber(lo) + " to " + shortNumber(hi) + "\"" : std::string();
}

std::string numberCell(const std::optional<double>& v, const std::string& extra = "") {
  return "<td data-value=\"" + sortValue(v) + "\"" + extra + ">" + shortNumber(v) + "</td>";
}

std::string list(const std::vector<std::string>& names) { return joined(names, ", ", escapeHtml); }

// What a figure of the analysis shows (docs/study.md, "The files"), by its file's stem, for an analysis whose
// results.json gives no caption; a figure the page does not know is captioned by its file name.
std::string figureCaption(const std::string& file) {
  static const std::map<std::string, std::string> kCaptions = {
      {"error_curves", "Relative RMSE r* per material, the materials sorted by the reference model's r* (log axis)"},
      {"heat_map", "Relative RMSE r* per material and model, on a log colour scale"},
      {"critical_difference", "Critical-difference diagram: the models' mean ranks, joined where they do not differ significantly"},
      {"brdf_vs_image", "BRDF-space error (E1, E2) against image error r*, log-log, one point per material and model"},
      {"perceptual", "r*, \xEA\x9F\xBBLIP, E1 and E2 of the shared fits against the perceived distance"},
  };
  const auto it = kCaptions.find(std::filesystem::path(file).stem().string());
  return it != kCaptions.end() ? it->second : file;
}

// The table's text columns, then its number columns, in order.
constexpr const char* kTextColumns[] = {"Material", "Database", "Class", "Lighting", "Scene", "Model", "Fit"};
constexpr const char* kNumberColumns[] = {"rRMSE", "\xEA\x9F\xBBLIP", "lum.", "E1", "E2", "closest"};

// The page's header: what the study covers, its sheets' settings and links to each scene and lighting's sheets.
void pageHeader(std::ostringstream& h, const study::StudyPlan& plan, const std::vector<study::StudyRow>& rows) {
  std::set<std::string> databases;
  for (const study::PlannedMaterial& m : plan.materials) databases.insert(m.database);
  h << "<header class=\"site\">\n<h1>A study of analytic BRDF models against measured data</h1>\n<p>"
    << plan.materials.size() << " materials (" << list({databases.begin(), databases.end()}) << ") under " << plan.lightings.size()
    << (plan.lightings.size() == 1 ? " lighting" : " lightings") << " (" << list(plan.lightings) << ") in " << plan.scenes.size()
    << (plan.scenes.size() == 1 ? " scene" : " scenes") << " (" << list(plan.scenes) << "): " << rows.size()
    << " rows, one per model of every sheet.";
  if (!rows.empty())
    h << " Every sheet: " << rows.front().width << "\xC3\x97" << rows.front().height << " panels, " << rows.front().spp
      << " samples per pixel, seed " << rows.front().seed << ".";
  h << "</p>\n<p>The sheets of each scene and lighting: ";
  bool first = true;
  for (const std::string& scene : plan.scenes)
    for (const std::string& lighting : plan.lightings) {
      h << (first ? "" : ", ") << "<a href=\"" << escapeHtml(study_layout::sheetsSite(scene, lighting)) << layout::kIndex << "\">"
        << escapeHtml(scene + " / " + lighting) << "</a>";
      first = false;
    }
  h << ".</p>\n</header>\n";
}

// The analysis's figures, each captioned by what it shows.
void figuresSection(std::ostringstream& h, const StudyFiles& files) {
  if (files.figures.empty()) return;
  h << "<h2 id=\"figures-heading\">Figures</h2>\n";
  for (const std::string& f : files.figures) {
    const std::string src = escapeHtml(study_layout::analysisFile(f));
    const auto known = files.captions.find(std::filesystem::path(f).stem().string());
    const std::string caption = known != files.captions.end() ? known->second : figureCaption(f);
    h << "<figure class=\"study-figure\"><a href=\"" << src << "\"><img src=\"" << src << "\" alt=\"" << escapeHtml(caption)
      << "\" loading=\"lazy\" style=\"max-width:100%\"></a><figcaption>" << escapeHtml(caption) << " (<code>" << escapeHtml(f)
      << "</code>)</figcaption></figure>\n";
  }
}

// Every row of the study, one model on one sheet, linking to the sheet's page.
void rowsTable(std::ostringstream& h, const std::vector<study::StudyRow>& rows) {
  h << "<h2 id=\"materials-heading\">Rows</h2>\n<div class=\"controls\"><label for=\"filter\">Filter</label>"
       "<input id=\"filter\" type=\"search\" placeholder=\"words of a material, database, lighting, scene, model or fit\" autocomplete=\"off\">"
       "<span id=\"shown\" class=\"muted\" aria-live=\"polite\">"
    << rows.size() << " rows</span></div>\n<div class=\"table-wrap\">\n<table id=\"materials\" data-noun=\"rows\" aria-labelledby=\"materials-heading\">\n<thead><tr>";
  int col = 0;
  for (const char* c : kTextColumns)
    h << "<th scope=\"col\" class=\"text\" data-col=\"" << col++ << "\" data-type=\"text\"><button class=\"sort\" type=\"button\">" << c
      << "</button></th>";
  for (const char* c : kNumberColumns)
    h << "<th scope=\"col\" data-col=\"" << col++ << "\" data-type=\"number\"><button class=\"sort\" type=\"button\">" << c
      << "</button></th>";
  h << "<th scope=\"col\" class=\"text\">Warning</th></tr></thead>\n<tbody class=\"rows\">\n";
  for (const study::StudyRow& r : rows) {
    const std::string page = study_layout::sheetsSite(r.scene, r.lighting) + layout::materialPage(r.material);
    // Every text column's words, so the filter finds a row by any of them.
    h << "<tr data-name=\"" << escapeHtml(joined(std::vector<std::string>{r.material, r.database, r.materialClass, r.lighting, r.scene, r.label, r.fit, r.fitSource}, " "))
      << "\" data-verdict=\""
      << escapeHtml(r.closest ? "closest" : r.tied ? "tie" : "") << "\">"
      << "<td class=\"name\" data-value=\"" << escapeHtml(r.material) << "\"><a href=\"" << escapeHtml(page) << "\">"
      << escapeHtml(r.material) << "</a></td><td class=\"text\">" << escapeHtml(r.database) << "</td><td class=\"text\">"
      << escapeHtml(r.materialClass.empty() ? "–" : r.materialClass) << "</td><td class=\"text\">" << escapeHtml(r.lighting)
      << "</td><td class=\"text\">" << escapeHtml(r.scene) << "</td><td class=\"text\">" << escapeHtml(r.label)
      << "</td><td class=\"text\">" << escapeHtml(r.fit + " (" + r.fitSource + ")") << "</td>"
      << numberCell(r.rrmse, interval(r.rrmseLo, r.rrmseHi)) << numberCell(r.flip, interval(r.flipLo, r.flipHi))
      << numberCell(r.luminanceRatio) << numberCell(r.e1) << numberCell(r.e2);
    if (r.closest || r.tied)
      h << "<td class=\"closest-mark\" data-value=\"" << (r.closest ? "1" : "0.5") << "\">" << (r.closest ? "closest" : "tie") << "</td>";
    else
      h << "<td data-value=\"0\"></td>";
    h << "<td class=\"text\">" << escapeHtml(r.warning) << "</td></tr>\n";
  }
  h << "</tbody>\n</table>\n</div>\n<p class=\"muted\">A row is one model on one sheet; its material links to the sheet's page. "
       "rRMSE: relative RMSE with the render noise taken out (hover for its 95 % interval); \xEA\x9F\xBBLIP: mean HDR-\xEA\x9F\xBBLIP; "
       "lum.: luminance ratio; E1, E2: the fit's error against the measured table; closest: the sheet's verdict (a tie where "
       "the intervals do not separate).</p>\n";
}

}  // namespace

std::string studyPage(const study::StudyPlan& plan, const std::vector<study::StudyRow>& rows, const StudyFiles& files) {
  std::ostringstream h;
  h << pageStart(formatted("glossy study: %zu materials", plan.materials.size()), "");
  pageHeader(h, plan, rows);
  h << "<main>\n";
  if (!files.summary.empty())
    h << "<h2 id=\"summary-heading\">Summary</h2>\n<div class=\"study-summary\">\n" << markdownToHtml(files.summary) << "</div>\n";
  figuresSection(h, files);
  if (!files.others.empty()) {
    h << "<h2 id=\"files-heading\">Tables and data</h2>\n<ul class=\"study-files\">\n";
    for (const std::string& f : files.others)
      h << "<li><a href=\"" << escapeHtml(study_layout::analysisFile(f)) << "\">" << escapeHtml(f) << "</a></li>\n";
    h << "</ul>\n";
  }
  rowsTable(h, rows);
  h << "</main>\n";
  h << pageEnd("Made by <code>glossy report</code> from the output of <code>glossy study</code> (docs/study.md).");
  return h.str();
}

}  // namespace glossy::report
