// glossy error: E1 and E2 of every fit of a material file against a measured table (docs/fitting.md).
#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "materials/fitting/metric.h"
#include "materials/params/material_file.h"
#include "renderer/app/brdf_options.h"
#include "renderer/cli/command.h"
#include "renderer/cli/output.h"

#include <nlohmann/json.hpp>


namespace glossy::cli {

namespace {

struct ErrorOptions {
  std::string measured, merlDir, material;
  bool json = false;
};

int runError(const ErrorOptions& o) {
  const MaterialFile material = loadMaterialFile(o.material);
  std::filesystem::path tablePath;
  if (!o.measured.empty()) tablePath = findMeasured(o.measured, o.merlDir);
  else if (auto p = resolveMeasured(material, o.merlDir)) tablePath = *p;
  else throw InputError(o.material + ": names no measured data that exists; pass --measured FILE");
  const auto table = loadMeasured(tablePath);
  const MetricData e1(*table, Metric::E1), e2(*table, Metric::E2);

  std::string out;
  if (o.json) {
    nlohmann::json fits = nlohmann::json::array();
    for (const Fit& fit : material.fits) {
      const Brdf brdf = makeBrdf(fit);
      nlohmann::json f = {{"fit", fit.id.str()}, {"E1", e1.error(brdf)}, {"E2", e2.error(brdf)}};
      if (fit.error) f["stored"] = *fit.error;
      fits.push_back(std::move(f));
    }
    const nlohmann::json doc = {{"material", material.name},     {"measured", measuredLabel(tablePath)},
                                {"grid", MetricGrid::describe()}, {"validPairs", e1.validPairs()},
                                {"fits", std::move(fits)}};
    out = doc.dump() + "\n";
  } else {
    out += formatted("%s against %s (%zu of %zu grid pairs measured)\n", material.name.c_str(),
                     measuredLabel(tablePath).c_str(), e1.validPairs(), MetricGrid::kPairs);
    out += formatted("%-22s %12s %12s %12s\n", "fit", "E1", "E2", "stored");
    for (const Fit& fit : material.fits) {
      const Brdf brdf = makeBrdf(fit);
      const std::string stored = fit.error ? formatted("%.6g", *fit.error) : "-";
      out += formatted("%-22s %12.6g %12.6g %12s\n", fit.id.str().c_str(), e1.error(brdf), e2.error(brdf), stored.c_str());
    }
  }
  return writeStdout(out);
}

}  // namespace

Command addErrorCommand(CLI::App& parent) {
  auto o = std::make_shared<ErrorOptions>();
  CLI::App* app = parent.add_subcommand("error", "E1 and E2 of every fit of a material against measured data");
  app->add_option("--material", o->material, "material TOML")->required();
  app->add_option("--measured", o->measured, "MERL table or .nbrdf network (default: the data the material names, else its embedded network)");
  app->add_option("--merl-dir", o->merlDir, "where to look for the table (else $GLOSSY_MERL_DIR)");
  app->add_flag("--json", o->json, "one JSON object on stdout instead of the table");
  return {app, [o] { return runError(*o); }};
}

}  // namespace glossy::cli
