// glossy: compare analytic BRDF models with measured ones. Exit status (shared/spec/interfaces.md):
// 0 success, 2 bad usage or bad input (one line on stderr naming the file and problem), 1 anything else.
#include "renderer/util/atomic_file.h"
#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "renderer/util/build_info.h"
#include "renderer/util/notes.h"
#include "materials/params/material_file.h"
#include "renderer/cli/command.h"

#include <algorithm>
#include <iostream>
#include <vector>

int main(int argc, char** argv) {
  using namespace glossy;
  removeTemporariesOnSignal();  // an interrupted write leaves no NAME.exr.tmp.* behind
  CLI::App app{"glossy " GLOSSY_VERSION ": render and compare glossy BRDF models (Löw et al. 2012) with measured data"};
  app.set_version_flag("--version", std::string(glossyVersion()) + " (" + std::string(glossyCommit()) + ")");
  app.require_subcommand(1);
  std::vector<cli::Command> commands = {cli::addErrorCommand(app),  cli::addEvalCommand(app),   cli::addFitCommand(app),
                                        cli::addImportCommand(app), cli::addListCommand(app),   cli::addMergeCommand(app),
                                        cli::addPlotCommand(app),   cli::addRenderCommand(app), cli::addReportCommand(app),
                                        cli::addSampleCommand(app), cli::addSheetCommand(app),  cli::addSheetsCommand(app),
                                        cli::addStudyCommand(app)};

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    // CLI11's message quotes the argument as given: it passes safeLine like every other message.
    std::string what = e.what();
    while (!what.empty() && what.back() == '\n') what.pop_back();
    std::replace(what.begin(), what.end(), '\n', ' ');
    std::cerr << "glossy: " << safeLine(what) << " (see glossy --help)\n";
    return 2;
  }

  // Notes wait for the input to prove good (renderer/util/notes.h): a bad-input error is the only line.
  try {
    for (const cli::Command& c : commands)
      if (c.app->parsed()) {
        // Checked here for every command that takes --merl-dir: a folder that is not one would otherwise be
        // passed over in silence, the tables looked for elsewhere or not at all.
        if (const CLI::Option* merlDir = c.app->get_option_no_throw("--merl-dir")) {
          const std::string given = merlDir->count() > 0 ? merlDir->as<std::string>() : std::string();
          if (merlDir->count() > 0 && given.empty()) throw InputError("--merl-dir: an empty path");
          checkMerlDirs(given, "--merl-dir");
        }
        const int status = c.run();
        flushNotes();
        return status;
      }
    return 2;
  } catch (const InputError& e) {
    discardNotes();
    std::cerr << "glossy: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    flushNotes();
    std::cerr << "glossy: " << safeLine(e.what()) << "\n";
    return 1;
  }
}
