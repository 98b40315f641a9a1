#include "renderer/study/study_methods.h"

#include "materials/core/text.h"
#include "renderer/study/study_tables.h"

#include <map>
#include <set>
#include <vector>

namespace glossy::study {

namespace {

using Json = nlohmann::ordered_json;

// What differs between the two renderings of one paragraph: the plain text of names is escaped for LaTeX,
// symbols are its math.
struct Markup {
  std::string (*text)(const std::string&);
  const char *rstar, *times, *alpha, *chi2, *dash, *le, *pct;
};

std::string plain(const std::string& s) { return s; }

const Markup kMarkdown{plain, "r\\*", "×", "α", "χ²", "–", "≤", "%"};
const Markup kLatex{latexEscape, "$r^*$", "$\\times$", "$\\alpha$", "$\\chi^2$", "--", "$\\le$", "\\%"};

std::string number(double v) { return formatted("%.6g", v); }

// "a", "a and b", "a, b and c".
std::string listed(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) out += (i == 0 ? "" : (i + 1 == items.size() ? " and " : ", ")) + items[i];
  return out;
}

// "0.8,0.8,0.9" of a constant environment's description ("constant 0.8,0.8,0.9").
std::string constantOf(const std::string& description) {
  const std::string prefix = "constant ";
  return description.starts_with(prefix) ? "(" + description.substr(prefix.size()) + ")" : description;
}

std::string plural(std::size_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// Who made a fit: a published fit is its paper's, named by its metric (Ngan et al. 2005's, Bagher et al.
// 2012's, else Löw et al. 2012's E1 or E2); glossy's own says so.
std::string fitSourceText(const Json& f, const Markup& m) {
  if (f["source"] == "glossy") return "glossy's own fit";
  if (f["metric"] == "Ngan05") return "the fit published by Ngan et al. (2005)";
  if (f["metric"] == "Bagher12") return "the fit published by Bagher et al. (2012)";
  return std::string("the fit published by L") + (m.text == plain ? "ö" : "\\\"{o}") + "w et al. (2012)";
}

// What was rendered: the materials by database and kind of measured panel, the lightings and scenes, the
// sheets, and the glossy that rendered them.
std::string renderingText(const Json& r, const Json* p, const Markup& m) {
  const auto t = m.text;
  std::string out;
  const Json& counts = r["counts"];
  std::vector<std::string> dbs;
  if (p) {
    for (const Json& d : (*p)["databases"]) {
      // What the measured panels are: the measured tables, or NBRDF networks' reconstructions of them.
      std::vector<std::string> kinds;
      for (const auto& [kind, n] : d["measured"].items()) {
        const bool one = n.get<int>() == 1;
        const std::string what = kind == "MERL table"             ? (one ? "measured table" : "measured tables")
                                 : kind == "NBRDF reconstruction" ? (one ? "NBRDF reconstruction" : "NBRDF reconstructions")
                                                                  : "without measured data";
        kinds.push_back(d["measured"].size() == 1 ? what : std::to_string(n.get<int>()) + " " + what);
      }
      dbs.push_back(std::to_string(d["materials"].get<int>()) + " from " + t(d["database"].get<std::string>()) + " (" + listed(kinds) + ")");
    }
  }
  const std::string version = r["glossy"]["version"].get<std::string>(), commit = r["glossy"]["commit"].get<std::string>();
  out += "We rendered " + plural(std::size_t(counts["materials"].get<int>()), "measured material", "measured materials");
  if (!dbs.empty()) out += ": " + listed(dbs) + ",";
  if (p) {
    std::vector<std::string> lightings, scenes;
    for (const Json& l : (*p)["lightings"]) {
      // From its parts rather than the environment's own description, whose degree sign LaTeX lacks.
      std::string d = l["kind"] == "sky" ? "glossy's built-in sky"
                      : l["kind"] == "map" ? "the environment map " + t(l["map"].get<std::string>())
                                           : "a constant environment of radiance " + t(constantOf(l["description"].get<std::string>()));
      if (l["rotate"].get<double>() != 0.0) d += " rotated by " + number(l["rotate"].get<double>()) + " degrees";
      lightings.push_back(t(l["name"].get<std::string>()) + ": " + d);
    }
    for (const Json& s : (*p)["scenes"])
      scenes.push_back(t(s["name"].get<std::string>()) +
                       (s["builtin"].is_null() ? ": " + t(s["file"].get<std::string>()) : ": glossy's " + t(s["builtin"].get<std::string>()) + " scene"));
    out += " under " + plural(lightings.size(), "lighting", "lightings") + " (" + listed(lightings) + ") in " +
           plural(scenes.size(), "scene", "scenes") + " (" + listed(scenes) + ")";
  }
  out += ", " + plural(std::size_t(counts["sheets"].get<int>()), "sheet", "sheets") + " in all, with glossy " + t(version) +
         " (commit " + t(commit) + "), a physically based path tracer on Embree. ";
  return out;
}

// The fits: each model's, by who made them.
std::string fitsText(const Json& r, const Markup& m) {
  const auto t = m.text;
  std::vector<std::string> models;
  for (const Json& model : r["fits"]) {
    std::vector<std::string> fits;
    for (const Json& f : model["fits"]) {
      std::vector<std::string> on;
      for (const Json& d : f["databases"]) on.push_back(t(d.get<std::string>()));
      fits.push_back(fitSourceText(f, m) + (model["fits"].size() > 1 ? " on " + listed(on) : std::string()));
    }
    models.push_back(t(model["model"].get<std::string>()) + " (" + listed(fits) + ")");
  }
  return "Each sheet shows the measured material beside " + plural(models.size(), "fitted model", "fitted models") + ": " + listed(models) + ". ";
}

// The panels: their size, how long they were rendered, their paths and seed (`s`: provenance.settings).
std::string panelsText(const Json& s, const Markup& m) {
  std::string out = "Each panel is " + std::to_string(s["width"].get<int>()) + " " + m.times + " " + std::to_string(s["height"].get<int>()) + " pixels";
  if (s["targetError"].get<double>() > 0.0)
    out += ", rendered until every model's " + std::string(m.rstar) + " interval has a half-width of at most " + number(s["targetError"].get<double>()) +
           " or " + std::to_string(s["spp"].get<int>()) + " samples per pixel";
  else if (s["time"].get<double>() > 0.0)
    out += ", rendered for " + number(s["time"].get<double>()) + " s per panel (at most " + std::to_string(s["spp"].get<int>()) + " samples per pixel)";
  else
    out += " at " + std::to_string(s["spp"].get<int>()) + " samples per pixel";
  out += ", with paths of up to " + std::to_string(s["maxDepth"].get<int>()) + " bounces, " + std::to_string(s["lightSamples"].get<int>()) +
         " light samples at the first vertex, shared by every panel, and seed " + std::to_string(s["seed"].get<std::uint64_t>()) + ". ";
  return out;
}

// How large the render noise is, and what no interval includes: the bias it gives r* where it is large.
std::string renderNoiseText(const Json& r, const Markup& m) {
  if (!r.contains("renderNoise") || r["renderNoise"]["medianHalfWidth"].is_null()) return "";
  const Json& n = r["renderNoise"];
  return "; the sheets' " + std::string(m.rstar) + " intervals have a median half-width of " + formatted("%.2g", n["medianHalfWidth"].get<double>()) +
         " (90 " + m.pct + " of them at most " + formatted("%.2g", n["p90HalfWidth"].get<double>()) + "), and where that noise is large it biases " +
         m.rstar + " low and weakens its correlations, which the intervals do not include";
}

// The statistics: r*, materials as the unit, the rank tests, the effect size and the intervals.
std::string statisticsText(const Json& r, const Markup& m) {
  return "A model's image error is the noise-free relative RMSE " + std::string(m.rstar) +
         " = ||P - M|| / ||M|| of its panel P against the measured panel M, estimated with the render noise taken out; lower is better. "
         "Materials are the unit of analysis: a model's " + m.rstar + " on a material is its mean over the material's sheets. "
         "The models are ranked by " + m.rstar + " on each material, and their mean ranks compared with the Friedman test and its "
         "Iman" + m.dash + "Davenport F form over the " + std::to_string(r["friedman"]["materials"].get<int>()) +
         " materials that have every model; every pair is compared with a two-sided Wilcoxon signed-rank test (zero differences dropped; "
         "the exact null distribution for up to 25 non-zero differences without ties, else the normal approximation with the tie "
         "correction; no test with fewer than 6), Holm-corrected at " + m.alpha + " = 0.05, and models no pair of which is separated "
         "form a group. As an effect size, \"X closer than Y\" is the share of materials on which X's " + m.rstar +
         " is below Y's (a tie counts one half). Every interval is a 95 " + m.pct + " percentile bootstrap interval over materials (" +
         std::to_string(r["resamples"].get<int>()) + " resamples, each drawing materials with replacement with all their sheets; seed " +
         std::to_string(r["seed"].get<std::uint64_t>()) + "), which carries each sheet's render noise into its spread" + renderNoiseText(r, m) + ".";
}

std::string paragraph(const Json& r, const Markup& m) {
  const Json* p = r.contains("provenance") && r["provenance"].contains("settings") ? &r["provenance"] : nullptr;
  return renderingText(r, p, m) + fitsText(r, m) + (p ? panelsText((*p)["settings"], m) : std::string()) + statisticsText(r, m);
}

}  // namespace

std::string methodsMarkdown(const Json& results) { return paragraph(results, kMarkdown) + "\n"; }

std::string methodsTex(const Json& results) {
  return "% glossy study: the methods, generated from results.json (" + results["glossy"]["version"].get<std::string>() + ", " +
         results["glossy"]["commit"].get<std::string>() + ").\n" + paragraph(results, kLatex) + "\n";
}

}  // namespace glossy::study
