#include "renderer/app/fit_output.h"

#include "renderer/util/atomic_file.h"
#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "materials/params/material_name.h"
#include "renderer/app/brdf_options.h"

#include <ctime>

namespace glossy::app {

namespace {

std::string todayUtc() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buf[16];
  return std::string(buf, std::strftime(buf, sizeof buf, "%Y-%m-%d", &utc));
}

// "E1 = 0.0363, fitted to alum-bronze.binary.xz on 2026-12-01", as much as the fit records.
std::string describe(const Fit& f) {
  std::string s;
  if (f.error) s += f.id.metric + formatted(" = %.6g", *f.error);
  if (!f.data.empty()) s += (s.empty() ? "fitted to " : ", fitted to ") + f.data;
  if (!f.date.empty()) s += " on " + f.date;
  return s.empty() ? s : " (" + s + ")";
}

}  // namespace

std::string materialNameOf(const std::filesystem::path& data) {
  std::string name = data.filename().string();
  for (std::string_view suffix : {".nbrdf", ".xz", ".binary"})
    if (name.size() > suffix.size() && name.ends_with(suffix)) name.resize(name.size() - suffix.size());
  // It names --out-dir's NAME.toml and the file's `name`, which the loader holds to the same rule.
  checkMaterialName(name, data.string());
  return name;
}

MaterialFile materialForFit(const std::filesystem::path& path, const std::filesystem::path& data) {
  if (std::error_code ec; !path.empty() && std::filesystem::exists(path, ec)) {
    MaterialFile material = loadMaterialFile(path);
    // A fit belongs in its own material's file only: A's fit stored in B's file would pass for B's, and
    // replace B's own. The file's material is its measured data's, or its name when it names no data.
    const std::string ofData = materialNameOf(data);
    const std::string ofFile = material.measured.empty() ? material.name : materialNameOf(material.measured);
    if (ofFile != ofData)
      throw InputError(path.string() + ": is the parameter file of " + ofFile + (material.measured.empty() ? "" : " (measured by " + material.measured + ")") +
                       ", not of " + data.filename().string() + "; a fit goes into its own material's file");
    return material;
  }
  // `measured` names the data as resolveMeasured() finds it again: NAME.binary also finds NAME.binary.xz.
  std::string measured = data.filename().string();
  if (measured.ends_with(".xz")) measured.resize(measured.size() - 3);
  return {.name = materialNameOf(data), .measured = measured, .source = "glossy fit to " + data.filename().string(), .fits = {}, .path = {}};
}

void stampGlossysFit(Fit& fit, const std::filesystem::path& data) {
  fit.id.by = FitId::kGlossy;
  fit.source.clear();  // data, database and date say it
  fit.data = data.filename().string();  // the name, not the local path, which means nothing elsewhere
  fit.database = measuredDatabase(data);
  fit.date = todayUtc();
}

std::string putGlossysFit(MaterialFile& material, Fit fit, bool replacePublished) {
  std::string said;
  const FitId published{fit.id.model, fit.id.metric};
  if (const Fit* old = material.findExact(fit.id)) said = "replaces glossy's earlier " + fit.id.str() + " fit" + describe(*old);
  if (material.findExact(published)) {
    if (replacePublished) {
      std::erase_if(material.fits, [&](const Fit& f) { return f.id == published; });
      said += (said.empty() ? "" : "; ") + std::string("removes the published ") + published.str() + " fit (--replace)";
    } else {
      said += (said.empty() ? "" : "; ") + std::string("the published ") + published.str() + " fit stays beside it (--replace removes it)";
    }
  }
  material.put(std::move(fit));
  return said;
}

std::string writeGlossysFit(const std::filesystem::path& path, const std::filesystem::path& data, const Fit& fit, bool replacePublished) {
  MaterialFile material = materialForFit(path, data);
  const std::string said = putGlossysFit(material, fit, replacePublished);
  writeFileAtomically(path, toToml(material));
  return said;
}

}  // namespace glossy::app
