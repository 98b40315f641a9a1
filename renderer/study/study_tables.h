// The study's tables as files: its rows as CSV and JSON (one row per material × lighting × scene × model,
// every field of StudyRow). Numbers are written as the shortest text that reads back as the same value —
// a float32 figure (the sheets store them so) as its shortest float32 form (at most 9 significant digits),
// any other as its shortest double form — so that the files read back exactly and claim no precision the
// figures lack; an absent figure is an empty field or null.
#pragma once

#include "renderer/study/study_row.h"

#include <nlohmann/json.hpp>

#include <span>
#include <string>

namespace glossy::study {

std::string rowsCsv(std::span<const StudyRow> rows);
nlohmann::ordered_json rowsJson(std::span<const StudyRow> rows);
// `s` as LaTeX text: its special characters escaped, the few non-ASCII characters glossy's own words use
// (°, ö, –, ×, ρ, ², ≥) as LaTeX commands, and any other non-ASCII character as "?", so that the file compiles
// with pdflatex and no package.
std::string latexEscape(const std::string& s);
// An interval of results.json as the tables print it: "0.0123 [0.0110, 0.0135]" at `decimals` places,
// "--" when absent.
std::string intervalCell(const nlohmann::ordered_json& interval, int decimals = 4);

}  // namespace glossy::study
