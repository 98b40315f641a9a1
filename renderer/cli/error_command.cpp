// glossy error: E1 and E2 of every fit of a material file against a measured table (docs/fitting.md).
#include "materials/core/input_error.h"
#include "materials/fitting/metric.h"
#include "materials/params/material_file.h"
#include "renderer/cli/brdf_options.h"
#include "renderer/cli/command.h"
#include "renderer/cli/number_format.h"

#include <cstdio>
#include <iostream>

namespace glossy::cli {

namespace {

struct ErrorOptions {
  std::string measured, merlDir, material;
  bool json = false;
};

std::string jsonString(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

int runError(const ErrorOptions& o) {
  const MaterialFile material = loadMaterialFile(o.material);
  std::filesystem::path tablePath;
  if (!o.measured.empty()) tablePath = findMeasuredTable(o.measured, o.merlDir);
  else if (auto p = resolveMeasured(material, o.merlDir)) tablePath = *p;
  else throw InputError(o.material + ": names no measured table that exists; pass --measured FILE");
  const auto table = loadMerlTable(tablePath);
  const MetricData e1(*table, Metric::E1), e2(*table, Metric::E2);

  std::string out;
  if (o.json) {
    out += "{\"material\": " + jsonString(material.name) + ", \"measured\": " + jsonString(tablePath.filename().string()) +
           ", \"grid\": " + jsonString(MetricGrid::describe()) + ", \"validPairs\": " + std::to_string(e1.validPairs()) +
           ", \"fits\": [";
  } else {
    char line[160];
    std::snprintf(line, sizeof line, "%s against %s (%zu of %zu grid pairs measured)\n", material.name.c_str(),
                  tablePath.filename().string().c_str(), e1.validPairs(), MetricGrid::kPairs);
    out += line;
    std::snprintf(line, sizeof line, "%-22s %12s %12s %12s\n", "fit", "E1", "E2", "stored");
    out += line;
  }
  bool first = true;
  for (const Fit& fit : material.fits) {
    const Brdf brdf = makeBrdf(fit);
    const double a = e1.error(brdf), b = e2.error(brdf);
    if (o.json) {
      out += std::string(first ? "" : ", ") + "{\"fit\": " + jsonString(fit.id.str()) + ", \"E1\": ";
      appendNumber(out, a);
      out += ", \"E2\": ";
      appendNumber(out, b);
      if (fit.error) {
        out += ", \"stored\": ";
        appendNumber(out, *fit.error);
      }
      out += "}";
    } else {
      char line[160];
      std::snprintf(line, sizeof line, "%-22s %12.6g %12.6g %12s\n", fit.id.str().c_str(), a, b,
                    fit.error ? std::to_string(*fit.error).c_str() : "-");
      out += line;
    }
    first = false;
  }
  if (o.json) out += "]}\n";
  std::fwrite(out.data(), 1, out.size(), stdout);
  return std::fflush(stdout) == 0 ? 0 : 1;
}

}  // namespace

Command addErrorCommand(CLI::App& parent) {
  auto o = std::make_shared<ErrorOptions>();
  CLI::App* app = parent.add_subcommand("error", "E1 and E2 of every fit of a material against measured data");
  app->add_option("--material", o->material, "material TOML")->required();
  app->add_option("--measured", o->measured, "MERL table (default: the one the material names)");
  app->add_option("--merl-dir", o->merlDir, "where to look for the table (else $GLOSSY_MERL_DIR)");
  app->add_flag("--json", o->json, "one JSON object on stdout instead of the table");
  return {app, [o] { return runError(*o); }};
}

}  // namespace glossy::cli
