// A study's sheets read back into rows (study_row.h): one per analytic panel of every sheet the plan names
// (study_plan.h), from nothing but the study's output folder, so that `glossy study` (whole, or --analyse
// after its shards) and `glossy report` read the same rows.
#pragma once

#include "renderer/sheet/sheet_record.h"
#include "renderer/study/study_plan.h"
#include "renderer/study/study_row.h"

#include <filesystem>
#include <string>
#include <vector>

namespace glossy::study {

// The warning a sheet stands under, as its rows carry it (StudyRow::warning): its stored warnings and,
// without a verdict, why there is none, joined by "; "; "" when none.
std::string sheetWarning(const SheetRecord& sheet);

// The rows of one sheet: its non-empty analytic panels in grid order. `material`, `lighting` and `scene`
// say what the sheet is; `materialClass` is the class to give its rows ("" when unknown).
std::vector<StudyRow> sheetRows(const SheetRecord& sheet, const PlannedMaterial& material, const std::string& lighting,
                                const std::string& scene, const std::string& materialClass, const std::filesystem::path& relativeExr);

// Every row of the sheets `plan` names in `out`, sorted by material, lighting, scene and grid order.
// InputError naming the file when a sheet is missing or unreadable (a sheet not yet rendered among them), or
// when the plan's perceptual folder does not read. `glossy study` passes the plan it rendered, never one
// read back from the folder (study_folder.h).
std::vector<StudyRow> readStudyRows(const std::filesystem::path& out, const StudyPlan& plan);
// The same with the plan OUT/study.json holds (readPlan), for readers of a finished study (glossy report).
std::vector<StudyRow> readStudyRows(const std::filesystem::path& out);

}  // namespace glossy::study
