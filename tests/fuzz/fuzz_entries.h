// The fuzzed loaders' entries: each takes arbitrary bytes, hands them to one of glossy's input loaders the
// way the program would, and uses what it accepts. Bad input must come back as InputError (what the
// command line reports as bad input, exit status 2); anything else escaping, or a crash, is a bug. The
// libFuzzer targets (libfuzzer_main.cpp) and the default suite's fuzz_regression_test call these same
// functions, so every input kept in tests/fuzz/corpus and tests/fuzz/crashes is replayed by every build.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace glossy::fuzz {

using Bytes = std::span<const uint8_t>;

// A material parameter file (TOML).
void tomlEntry(Bytes data);
// A Neural BRDF network (.nbrdf, TOML).
void nbrdfEntry(Bytes data);
// A MERL table: first byte 'N': the bytes as the start of a full-size file whose remaining values are NaN;
// other even: the bytes as a whole file; other odd: a .binary.xz file (merl_entry.cpp).
void merlEntry(Bytes data);
// A glTF scene, .gltf JSON or .glb (told apart by the loader, by content).
void gltfEntry(Bytes data);
// An environment map: first byte odd: written as .exr, even: as .hdr; the rest is the file.
void envmapEntry(Bytes data);
// A sheet's EXR, as glossy report and glossy merge sheets read it; its panels cut out as the report does.
void sheetEntry(Bytes data);
// A plots folder's plots.json, as glossy report reads it, and the material page drawn with it.
void plotsEntry(Bytes data);
// A study file (TOML) as glossy study loads it, over a slice of the material library; its plan made and used.
void studyEntry(Bytes data);
// The perceptual dataset's tables: first byte odd: the rest is PerceptualDistances.csv, even: MaterialType.csv.
void perceptualEntry(Bytes data);
// A study output folder's study.json, as a resumed run, glossy study --analyse and glossy report read it.
void studyplanEntry(Bytes data);
// A sheet EXR inside a one-sheet study folder: the study's rows read from it, then analysed.
void studyrowsEntry(Bytes data);

struct Target {
  std::string_view name;  // tests/fuzz/corpus/NAME, tests/fuzz/crashes/NAME, fuzz_NAME
  void (*entry)(Bytes);
};

inline constexpr Target kTargets[] = {
    {"toml", tomlEntry}, {"nbrdf", nbrdfEntry}, {"merl", merlEntry}, {"gltf", gltfEntry},
    {"envmap", envmapEntry}, {"sheet", sheetEntry}, {"plots", plotsEntry}, {"study", studyEntry},
    {"perceptual", perceptualEntry}, {"studyplan", studyplanEntry}, {"studyrows", studyrowsEntry}};

}  // namespace glossy::fuzz
