// The study's tables as files: its rows as CSV and JSON (one row per material × lighting × scene × model,
// every field of StudyRow) and the per-model results as a LaTeX (booktabs) table. Numbers are written in
// full (%.17g) so that the files read back exactly; an absent figure is an empty field or null.
#pragma once

#include "renderer/study/study_row.h"

#include <nlohmann/json.hpp>

#include <span>
#include <string>

namespace glossy::study {

std::string rowsCsv(std::span<const StudyRow> rows);
nlohmann::ordered_json rowsJson(std::span<const StudyRow> rows);
// `models`: results.json's "models" array (label, closest, tied, meanRank, meanRrmse, medianRrmse).
std::string modelsTex(const nlohmann::ordered_json& models, int materials);
// Text as LaTeX shows it: its special characters escaped.
std::string latexEscape(const std::string& text);
// An interval of results.json as the tables print it: "0.0123 [0.0110, 0.0135]", "--" when absent.
std::string intervalCell(const nlohmann::ordered_json& interval);

}  // namespace glossy::study
