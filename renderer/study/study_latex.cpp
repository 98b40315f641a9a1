#include "renderer/study/study_latex.h"

#include "materials/core/text.h"
#include "renderer/study/study_tables.h"

#include <algorithm>
#include <map>
#include <set>

namespace glossy::study {

namespace {

using Json = nlohmann::ordered_json;

const Json* find(const Json& list, const char* key, const std::string& value) {
  for (const Json& j : list)
    if (j.contains(key) && j[key] == value) return &j;
  return nullptr;
}

std::string pText(const Json& p) {
  if (p.is_null()) return "--";
  const double v = p.get<double>();
  return v < 0.001 ? std::string("$<$0.001") : formatted("%.3f", v);
}

// Why the figures a table prints without an interval have none (small samples, resamples that all agree):
// gathered while the rows are written, then said in the caption, so no bare estimate reads as exact.
void noteAbsent(const Json& interval, std::set<std::string>& reasons) {
  if (!interval.is_object() || interval["estimate"].is_null() || !interval["lo"].is_null()) return;
  if (!interval.contains("reason") || !interval["reason"].is_string()) return;
  std::string reason = interval["reason"].get<std::string>();
  if (reason.starts_with("no interval: ")) reason.erase(0, 13);
  reasons.insert(reason);
}
std::string absentSentence(const std::set<std::string>& reasons) {
  if (reasons.empty()) return "";
  std::string s = " Figures without an interval have none:";
  for (const std::string& r : reasons) s += " " + latexEscape(r) + ";";
  s.back() = '.';
  return s;
}

// The Friedman test as the caption states it, or why there is none.
std::string friedmanText(const Json& f) {
  std::string friedman = "no Friedman test (" + latexEscape(f.value("reason", std::string("undefined"))) + ")";
  if (!f["p"].is_null()) {
    friedman = formatted("Friedman $\\chi^2 = %.2f$, df %d, $p$ = ", f["chiSquare"].get<double>(), f["df"].get<int>()) + pText(f["p"]);
    if (!f["pF"].is_null() && !f["imanDavenportF"].is_null())
      friedman += formatted("; Iman--Davenport $F = %.2f$, $p$ = ", f["imanDavenportF"].get<double>()) + pText(f["pF"]);
    else if (f["imanDavenportF"].is_null())
      friedman += "; Iman--Davenport $F$ infinite: every material ranks the models alike";
  }
  return friedman;
}

// Whose fits the rows are: a label covers the published fit on one database and glossy's on another.
std::string fitsSentence(const Json& results) {
  std::vector<std::string> glossyFits;
  for (const Json& model : results["fits"]) {
    std::vector<std::string> on;
    bool published = false;
    for (const Json& fit : model["fits"]) {
      if (fit["source"] != "glossy") {
        published = true;
        continue;
      }
      for (const Json& db : fit["databases"]) on.push_back(latexEscape(db.get<std::string>()));
    }
    if (on.empty()) continue;
    std::string entry = latexEscape(model["model"].get<std::string>());
    if (published) {
      entry += " on ";
      for (std::size_t i = 0; i < on.size(); ++i) entry += (i ? ", " : "") + on[i];
    }
    glossyFits.push_back(entry);
  }
  std::string sentence = "Every fit is the published one.";
  if (!glossyFits.empty()) {
    sentence = "glossy's own fits: ";
    for (std::size_t i = 0; i < glossyFits.size(); ++i) sentence += (i ? "; " : "") + glossyFits[i];
    sentence += "; the others are the published fits.";
  }
  return sentence;
}

// The models in rank order with their groups, verdicts, mean rank, mean and median r* and the share closer
// than the next model.
std::string modelsTable(const Json& results, const std::vector<std::string>& order) {
  const std::vector<std::string> letters = groupLetters(results, order);
  const Json& f = results["friedman"];
  const int materials = results["counts"]["materials"].get<int>();
  const int sheets = results["counts"]["sheets"].get<int>();
  const int resamples = results["resamples"].get<int>();
  std::string out =
      "% glossy study: the per-model results, generated from results.json (glossy " + results["glossy"]["version"].get<std::string>() +
      ", " + results["glossy"]["commit"].get<std::string>() + "). Needs \\usepackage{booktabs}.\n"
      "\\begin{table}[tbp]\n\\centering\n\\small\n"
      "\\caption{The models in order of their mean rank of $r^*$, the noise-free relative RMSE against the measured material (1 = closest), "
      "over the " + std::to_string(f.value("materials", 0)) + " of " + std::to_string(materials) + " materials that have every model (" +
      friedmanText(f) + "). Models sharing a letter are not separated by pairwise Wilcoxon signed-rank tests, Holm-corrected at "
      "$\\alpha = 0.05$. Closest and tied: the sheets, of " + std::to_string(sheets) +
      ", whose verdict names the model alone or in a tie. Closer than next: the share of materials on which the model's $r^*$ is "
      "below the next model's. Intervals: 95\\,\\% percentile bootstrap over materials (" + std::to_string(resamples) + " resamples). " +
      fitsSentence(results) + "}\n"
      "\\label{tab:glossy-study-models}\n"
      "\\begin{tabular}{llrrrlll}\n\\toprule\n"
      "Model & Group & Closest & Tied & Mean rank & Mean $r^*$ [95\\,\\% CI] & Median $r^*$ [95\\,\\% CI] & Closer than next [95\\,\\% CI] \\\\\n"
      "\\midrule\n";
  const Json& closer = results["closerThan"]["overall"];
  std::set<std::string> absent;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Json& m = *find(results["models"], "label", order[k]);
    noteAbsent(m["meanRrmse"], absent);
    noteAbsent(m["medianRrmse"], absent);
    std::string next = "--";
    if (k + 1 < order.size())
      for (const Json& c : closer)
        if (c["x"] == order[k] && c["y"] == order[k + 1]) {
          next = intervalCell(c["share"], 2);
          noteAbsent(c["share"], absent);
        }
    out += latexEscape(order[k]) + " & " + letters[k] + " & " + std::to_string(m["closest"].get<int>()) + " & " +
           std::to_string(m["tied"].get<int>()) + " & " +
           (m["meanRank"].is_null() ? std::string("--") : formatted("%.2f", m["meanRank"].get<double>())) + " & " +
           intervalCell(m["meanRrmse"]) + " & " + intervalCell(m["medianRrmse"]) + " & " + next + " \\\\\n";
  }
  out += "\\bottomrule\n\\end{tabular}\n\\end{table}\n\n";
  const std::string modelsLabel = "}\n\\label{tab:glossy-study-models}";
  out.insert(out.find(modelsLabel), absentSentence(absent));
  return out;
}

// Every pair, the better-ranked model first: the effect size beside the test.
std::string closerTable(const Json& results, const std::vector<std::string>& order) {
  const Json& closer = results["closerThan"]["overall"];
  std::set<std::string> absent;
  std::string out =
      "\\begin{table}[tbp]\n\\centering\n\\small\n"
      "\\caption{Each pair of models, X ranked ahead of Y: the share of materials on which X's $r^*$ is below Y's (a tie counts one "
      "half), with its 95\\,\\% percentile bootstrap interval over materials (" + std::to_string(results["resamples"].get<int>()) +
      " resamples), and the Holm-corrected $p$ of the two-sided Wilcoxon signed-rank test on the materials' $r^*$.}\n"
      "\\label{tab:glossy-study-closer}\n"
      "\\begin{tabular}{llrlr}\n\\toprule\n"
      "X & Y & Materials & X closer than Y [95\\,\\% CI] & Holm $p$ \\\\\n\\midrule\n";
  for (std::size_t a = 0; a < order.size(); ++a)
    for (std::size_t b = a + 1; b < order.size(); ++b) {
      const Json* c = nullptr;
      for (const Json& j : closer)
        if (j["x"] == order[a] && j["y"] == order[b]) c = &j;
      const Json* w = nullptr;
      for (const Json& j : results["wilcoxon"]["pairs"])
        if ((j["a"] == order[a] && j["b"] == order[b]) || (j["a"] == order[b] && j["b"] == order[a])) w = &j;
      if (c) noteAbsent((*c)["share"], absent);
      out += latexEscape(order[a]) + " & " + latexEscape(order[b]) + " & " + (c ? std::to_string((*c)["materials"].get<int>()) : "--") +
             " & " + (c ? intervalCell((*c)["share"], 2) : "--") + " & " + (w ? pText((*w)["pHolm"]) : "--") + " \\\\\n";
    }
  out += "\\bottomrule\n\\end{tabular}\n\\end{table}\n";
  const std::string closerLabel = "}\n\\label{tab:glossy-study-closer}";
  out.insert(out.find(closerLabel), absentSentence(absent));
  return out;
}

}  // namespace

std::vector<std::string> modelsByRank(const Json& results) {
  std::vector<std::pair<std::string, double>> models;
  for (const Json& m : results["models"])
    models.emplace_back(m["label"].get<std::string>(), m["meanRank"].is_null() ? 1e300 : m["meanRank"].get<double>());
  std::stable_sort(models.begin(), models.end(), [](const auto& a, const auto& b) { return std::tie(a.second, a.first) < std::tie(b.second, b.first); });
  std::vector<std::string> out;
  for (const auto& [label, rank] : models) out.push_back(label);
  return out;
}

std::vector<std::string> groupLetters(const Json& results, const std::vector<std::string>& order) {
  // Each group as the rank positions of its models: the cliques, and a model in none on its own; lettered
  // in the order of their first model.
  std::vector<std::vector<std::size_t>> groups;
  std::vector<bool> grouped(order.size(), false);
  for (const Json& clique : results["wilcoxon"]["cliques"]) {
    std::vector<std::size_t> g;
    for (const Json& label : clique)
      if (const auto it = std::find(order.begin(), order.end(), label.get<std::string>()); it != order.end()) {
        g.push_back(std::size_t(it - order.begin()));
        grouped[g.back()] = true;
      }
    std::sort(g.begin(), g.end());
    if (!g.empty()) groups.push_back(g);
  }
  for (std::size_t k = 0; k < order.size(); ++k)
    if (!grouped[k]) groups.push_back({k});
  std::stable_sort(groups.begin(), groups.end(), [](const auto& a, const auto& b) { return a.front() < b.front(); });
  std::vector<std::string> letters(order.size());
  for (std::size_t g = 0; g < groups.size(); ++g) {
    // a … z, then aa, ab, …: a study of more than 26 groups is not one table, but its letters stay distinct.
    const std::string letter = g < 26 ? std::string(1, char('a' + g)) : std::string(1, char('a' + g / 26 - 1)) + char('a' + g % 26);
    for (std::size_t k : groups[g]) letters[k] += (letters[k].empty() ? "" : ",") + letter;
  }
  return letters;
}

std::string modelsTex(const Json& results) {
  const std::vector<std::string> order = modelsByRank(results);
  return modelsTable(results, order) + closerTable(results, order);
}

}  // namespace glossy::study
