// Where glossy's fits go: into a material parameter file, marked as glossy's (MODEL:METRIC:glossy) with the
// data they were fitted to and the day, beside the published fits, which they never replace unasked
// (docs/fitting.md, "Output"). `glossy fit -o`, `glossy fit --out-dir` and Python's Fit.save all go
// through here.
#pragma once

#include "materials/params/material_file.h"

#include <filesystem>
#include <string>

namespace glossy::app {

// The material a table or network is of: "alum-bronze" for alum-bronze.binary.xz; InputError naming the
// file when that is no material name (material_name.h).
std::string materialNameOf(const std::filesystem::path& data);

// The parameter file a fit of `data` goes into: `path` read (and so validated) when it exists, else a new
// material named after the data and measured by it (whatever the new file is called).
MaterialFile materialForFit(const std::filesystem::path& path, const std::filesystem::path& data);

// Marks a fit that glossy made as glossy's, fitted to `data`, today (UTC).
void stampGlossysFit(Fit& fit, const std::filesystem::path& data);

// Puts glossy's fit into the material. A published fit of the same model and metric stays (removed only
// with replacePublished); glossy's earlier fit of them is replaced. Returns what happened to the fits that
// were there, for one line on stderr ("" when the fit was simply added).
std::string putGlossysFit(MaterialFile& material, Fit fit, bool replacePublished);

// Puts glossy's fit of `data` into the parameter file `path` (putGlossysFit) and writes it atomically. The
// caller holds the file's lock (output_lock.h): the file is read again here, so a fit another process put in
// before the lock was taken stays. Returns putGlossysFit's words.
std::string writeGlossysFit(const std::filesystem::path& path, const std::filesystem::path& data, const Fit& fit, bool replacePublished);

}  // namespace glossy::app
