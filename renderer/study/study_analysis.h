// The statistics of a study (docs/study.md, "The statistics"): rows in, files out. `glossy study` reads its
// sheets into StudyRows and hands them here; everything it reports about the models — verdicts per material
// and lighting, ranks and their tests, bootstrap intervals, the BRDF-space against image-space question,
// and the comparison with people's judgments — is computed and written by analyseStudy, so that the
// command, its tests and Python see the same numbers.
#pragma once

#include "renderer/study/study_provenance.h"
#include "renderer/study/study_row.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace glossy::study {

struct AnalysisOptions {
  std::uint64_t seed = 1;  // the bootstraps' seed: the same seed and rows give the same files
  int resamples = 2000;    // bootstrap resamples (percentile intervals)
  // ../shared/perceptual (renderer/study/perceptual.h); empty: no comparison with people.
  std::filesystem::path perceptualDir;
  // The label the per-material error curves are sorted by.
  std::string referenceModel = "Microfacet E2";
  // What the rows stand on (the study file, its settings, lightings, scenes, measured data), recorded in
  // results.json and the methods; the study file is kept as study.toml beside them. Absent: rows analysed
  // on their own, and the methods say only what the rows do.
  std::optional<StudyProvenance> provenance;
  // Told as each step starts (`step` of `steps`, from 1, and what it computes), for a progress line: the
  // bootstraps take minutes on a large study. Unset: nothing is told.
  std::function<void(int step, int steps, const std::string& what)> progress;
};

// The expected seconds of analyseStudy with `resamples` over `materials` materials and `models` models: the
// bootstraps dominate, and each draws every material for every pair of models (the pairwise shares) —
// measured at about 3.5 µs a resample × material × model² on the development machine (100 MERL
// materials, 6 models, 2,000 resamples: 25 s).
double expectedAnalysisSeconds(int resamples, std::size_t materials, std::size_t models);

struct AnalysisResult {
  std::string summary;                        // the headline text `glossy study` prints
  std::vector<std::filesystem::path> files;  // written, relative to the folder, in the order written
};

// Every statistic of docs/study.md over `rows`, written into `folder` (which must exist) atomically
// (renderer/util/atomic_file.h). Deterministic: the same rows, in any order, and the same options give
// byte-identical files. Rows without an rrmse are skipped and counted. Throws InputError for rows that
// cannot be a study (e.g. the same model twice on one sheet, a non-finite figure) and std::runtime_error
// if a file cannot be written.
AnalysisResult analyseStudy(std::span<const StudyRow> rows, const AnalysisOptions& options,
                            const std::filesystem::path& folder);

}  // namespace glossy::study
