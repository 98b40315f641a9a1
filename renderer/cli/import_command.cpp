// glossy import: the paper's published parameters (supplement text, .fit lines) → one TOML per material.
#include "renderer/util/atomic_file.h"
#include "materials/core/input_error.h"
#include "materials/params/importer.h"
#include "renderer/app/destination.h"
#include "renderer/output/inside_folder.h"
#include "renderer/cli/command.h"

#include <iostream>
#include <memory>

namespace glossy::cli {

namespace {

struct ImportOptions {
  std::vector<std::string> sources;
  std::string outDir;
  bool replace = false;
};

int runImport(const ImportOptions& o) {
  checkOutputFolder(o.outDir, "-o");
  Importer importer;
  for (const std::string& s : o.sources) importer.addFile(s);

  const std::filesystem::path dir = o.outDir;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create the output folder (" + ec.message() + ")");

  // Read every existing file before writing any, so that a malformed one stops the import untouched.
  std::vector<MaterialFile> merged;
  for (const std::string& name : importer.names()) {
    const std::filesystem::path path = dir / (name + ".toml");
    checkWriteInside(dir, path, "-o");
    MaterialFile existing;
    if (std::filesystem::exists(path, ec)) {
      try {
        existing = loadMaterialFile(path);
        // Even --replace never replaces a published fit with other values (importer.h).
        importer.checkKeepsPublished(existing, name);
      } catch (const InputError&) {
        // --replace writes over a file that does not load (it holds no fit that could be read), never over
        // one whose published fit the sources contradict.
        if (!o.replace || !existing.name.empty()) throw;
      }
      if (o.replace) existing = {};
    }
    merged.push_back(importer.mergeInto(std::move(existing), name));
  }
  size_t fits = 0;
  for (const MaterialFile& m : merged) {
    writeFileAtomically(dir / (m.name + ".toml"), toToml(m));
    fits += m.fits.size();
  }
  std::cout << "imported " << importer.fitCount() << " fits of " << merged.size() << " materials; " << dir.string()
            << " now holds " << fits << " fits for them\n";
  return 0;
}

}  // namespace

Command addImportCommand(CLI::App& parent) {
  auto o = std::make_shared<ImportOptions>();
  CLI::App* app = parent.add_subcommand("import",
      "Import published fits into parameter files, one NAME.toml per material in the output folder. Sources are "
      "the supplement's text (sections 'Material Name: X') and bbm .fit files (low_<model>_<E1|E2>.fit). Where "
      "both give a fit, the supplement's more precise values win. Fits already in an existing NAME.toml that the "
      "sources do not give are kept (unless --replace); a published fit there is never replaced by other values.");
  app->add_option("sources", o->sources, "Supplement text or .fit files")->required();
  app->add_option("-o,--out", o->outDir, "Output folder for the TOML files")->required();
  app->add_flag("--replace", o->replace, "Overwrite existing files instead of merging into them (a published fit in them that the sources contradict is still refused)");
  return {app, [o] { return runImport(*o); }};
}

}  // namespace glossy::cli
