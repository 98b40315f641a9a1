// Each subcommand registers its options on the parent CLI11 app and returns how to run it.
#pragma once

#include "materials/core/text.h"
#include "renderer/app/brdf_options.h"
#include "renderer/app/option_specs.h"
#include "renderer/app/scene_options.h"
#include "renderer/integrator/path_tracer.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace glossy::cli {

// The front end runs the app layer's jobs (renderer/app/).
using namespace glossy::app;

struct Command {
  CLI::App* app;
  std::function<int()> run;  // exit status; throws InputError for bad input
};

Command addErrorCommand(CLI::App& parent);
Command addEvalCommand(CLI::App& parent);
Command addFitCommand(CLI::App& parent);
Command addImportCommand(CLI::App& parent);
Command addListCommand(CLI::App& parent);
Command addMergeCommand(CLI::App& parent);
Command addPlotCommand(CLI::App& parent);
Command addRenderCommand(CLI::App& parent);
Command addReportCommand(CLI::App& parent);
Command addSampleCommand(CLI::App& parent);
Command addSheetCommand(CLI::App& parent);
Command addSheetsCommand(CLI::App& parent);
Command addStudyCommand(CLI::App& parent);

// An option of the table (renderer/app/option_specs.h) bound to `field`: its range, help and default.
// CLI::PositiveNumber lets "inf" through, and an infinite budget never ends; CLI11's own ranges print a
// double's limits with std::to_string (309 digits): the spec's check says it in one short line.
template <class T>
CLI::Option* addOption(CLI::App* app, const app::OptionSpec& spec, T& field) {
  return app->add_option(spec.flag(), field, spec.help)
      ->check(CLI::Validator(
          [&spec](std::string& text) {
            const std::optional<double> v = parseNumber(text);
            return v && spec.accepts(*v) ? std::string() : spec.refusal(text);
          },
          (spec.whole ? "INT in " : "NUMBER in ") + spec.range()))
      ->capture_default_str();
}

// An option of the table bound to its field (app::OptionField).
inline CLI::Option* addOption(CLI::App* app, const app::OptionField& f) {
  return std::visit([&](auto* field) { return addOption(app, *f.spec, *field); }, f.field);
}

// The options naming the scene (app/scene_options.h) and one BRDF (app/brdf_options.h).
void addSceneOptions(CLI::App* app, app::SceneOptions& o);
void addBrdfOptions(CLI::App* app, app::BrdfOptions& o);

}  // namespace glossy::cli
