// glossy eval: BRDF values for direction pairs read from stdin (shared/spec/interfaces.md).
#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "materials/core/unit_direction.h"
#include "materials/models/brdf.h"
#include "renderer/app/brdf_options.h"
#include "renderer/cli/command.h"
#include "renderer/cli/output.h"

#include <cmath>
#include <iostream>
#include <memory>
#include <string>

namespace glossy::cli {

namespace {

struct EvalOptions {
  BrdfOptions brdf;
  bool pdf = false;
};

// "Lx,Ly,Lz,Vx,Vy,Vz" → two unit vectors; throws InputError naming the stdin line.
std::pair<Vec3, Vec3> parseDirections(const std::string& line, size_t number) {
  const std::string where = "stdin line " + std::to_string(number);
  const auto v = parseNumberList(line);
  if (v && v->size() > 6) throw InputError(where + ": trailing text after 6 numbers in '" + line + "'");
  if (!v || v->size() != 6) throw InputError(where + ": expected 6 comma-separated numbers Lx,Ly,Lz,Vx,Vy,Vz, got '" + line + "'");
  Vec3 L((*v)[0], (*v)[1], (*v)[2]), V((*v)[3], (*v)[4], (*v)[5]);
  for (Vec3* d : {&L, &V})
    if (!makeUnitDirection(*d)) throw InputError(where + ": a direction is zero or not finite");
  return {L, V};
}

int runEval(const EvalOptions& o) {
  const Brdf brdf = o.brdf.load();

  // Parse everything first: bad input produces an error and no partial output.
  std::vector<std::pair<Vec3, Vec3>> pairs;
  std::string line;
  for (size_t n = 1; std::getline(std::cin, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    pairs.push_back(parseDirections(line, n));
  }
  std::string out;
  out.reserve(pairs.size() * 80);
  for (const auto& [L, V] : pairs) {
    const Rgb rho = eval(brdf, L, V);
    if (o.pdf)
      appendLine(out, {rho.r, rho.g, rho.b, pdf(brdf, L, V)});
    else
      appendLine(out, {rho.r, rho.g, rho.b});
  }
  return writeStdout(out);
}

}  // namespace

Command addEvalCommand(CLI::App& parent) {
  auto o = std::make_shared<EvalOptions>();
  CLI::App* app = parent.add_subcommand("eval",
      "Evaluate a BRDF. Reads lines Lx,Ly,Lz,Vx,Vy,Vz (local frame, N = +z, L toward the light, V toward the "
      "viewer) on stdin; writes R,G,B (with --pdf: R,G,B,pdf) per line on stdout in full double precision.");
  addBrdfOptions(app, o->brdf);
  app->add_flag("--pdf", o->pdf, "Also print the solid-angle pdf of the BRDF's sampler for L given V");
  return {app, [o] { return runEval(*o); }};
}

}  // namespace glossy::cli
