#include "renderer/app/brdf_options.h"

#include "materials/core/input_error.h"
#include "renderer/util/notes.h"
#include "materials/core/text.h"
#include "materials/nbrdf/neural_brdf.h"
#include "materials/params/material_file.h"

#include <cstdio>
#include <memory>

namespace glossy::app {

Brdf BrdfOptions::load() const {
  if (!measured.empty()) return Measured{loadMeasured(findMeasured(measured, merlDir))};
  const MaterialFile file = loadMaterialFile(material);
  const FitId id = FitId::parse(fit, "--fit");
  const Fit* found = file.find(id);
  if (!found) throw InputError(material + ": has no " + id.str() + " fit");
  Fit chosen = *found;
  if (!smoothFresnel.empty()) {
    if (id.model != Smooth::kName) throw InputError("--smooth-fresnel applies to smooth fits only, not " + id.str());
    chosen.params.set("fresnel", smoothFresnel);
  }
  return makeBrdf(chosen);
}

std::shared_ptr<const MerlTable> loadMeasured(const std::filesystem::path& path) {
  auto table = std::make_shared<const MerlTable>(path.extension() == ".nbrdf" ? NeuralBrdf::load(path).tabulate()
                                                                                : MerlTable::load(path));
  if (table->invalidBins() == MerlTable::kBins)
    throw InputError(table->source() + ": every bin is unmeasured (negative): the table holds no data");
  if (table->invalidBins() > 0)
    noteOnce(formatted("%s: %zu of %zu bins unmeasured (they evaluate to 0)", table->source().c_str(), table->invalidBins(),
                   MerlTable::kBins));
  return table;
}

std::string measuredDatabase(const std::filesystem::path& path) {
  if (path.extension() == ".nbrdf") return NeuralBrdf::load(path).label();
  std::error_code ec;
  return std::filesystem::exists(path.parent_path() / "nbrdf_weights", ec) ? "MERL (NBRDF reconstruction)" : "MERL";
}

std::string measuredLabel(const std::filesystem::path& path) { return measuredDatabase(path) + " " + path.string(); }

std::filesystem::path findMeasured(const std::string& given, const std::filesystem::path& merlDir) {
  const auto path = resolveMeasured(given, merlDir);
  if (!path) throw InputError(given + ": measured data not found (looked in --merl-dir, $GLOSSY_MERL_DIR, the working folder)");
  return *path;
}

}  // namespace glossy::app
