// glossy sample: directions drawn from a BRDF's sampler for one outgoing direction, with their pdf and
// weight, so that anyone can check the sampler (shared/spec/interfaces.md).
#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "materials/core/unit_direction.h"
#include "renderer/app/brdf_options.h"
#include "renderer/cli/command.h"
#include "renderer/cli/output.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

namespace glossy::cli {

namespace {

struct SampleOptions {
  BrdfOptions brdf;
  std::string wo;
  long long count = 0;
  uint64_t seed = 0;
};

Vec3 parseDirection(const std::string& text) {
  const auto v = parseNumberList(text);
  if (!v || v->size() != 3) throw InputError("--wo: '" + text + "' is not x,y,z");
  Vec3 d((*v)[0], (*v)[1], (*v)[2]);
  if (!makeUnitDirection(d)) throw InputError("--wo: '" + text + "' is zero or not finite");
  return d;
}

int runSample(const SampleOptions& o) {
  const Brdf brdf = o.brdf.load();
  const Vec3 V = parseDirection(o.wo);
  // Independent uniform numbers (not the renderer's low-discrepancy points), so the output is an i.i.d.
  // sample that a χ² test may take as multinomial.
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::string out;
  out.reserve(size_t(std::min<long long>(o.count, 1 << 20)) * 120);
  for (long long i = 0; i < o.count; ++i) {
    const double uLobe = uniform(rng), u1 = uniform(rng), u2 = uniform(rng);
    const BrdfSample s = sample(brdf, V, uLobe, Vec2(u1, u2));
    if (!s.valid())
      out += "0,0,0,0,0,0,0\n";
    else
      appendLine(out, {s.L.x, s.L.y, s.L.z, s.pdf, s.weight.r, s.weight.g, s.weight.b});
    if (out.size() > (1u << 24)) {
      std::fwrite(out.data(), 1, out.size(), stdout);
      out.clear();
    }
  }
  return writeStdout(out);
}

}  // namespace

Command addSampleCommand(CLI::App& parent) {
  auto o = std::make_shared<SampleOptions>();
  CLI::App* app = parent.add_subcommand("sample",
      "Draw directions from a BRDF's sampler for the outgoing direction --wo (local frame, N = +z). Writes N lines "
      "Lx,Ly,Lz,pdf,wR,wG,wB with w = ρ cos θ_L / pdf; an invalid sample (below the horizon, rejected) is the line "
      "0,0,0,0,0,0,0.");
  addBrdfOptions(app, o->brdf);
  app->add_option("--wo", o->wo, "Outgoing direction toward the viewer, x,y,z (normalised here)")->required();
  addOption(app, options::kSamples, o->count)->required();
  app->add_option("--seed", o->seed, "Seed of the uniform random numbers")->capture_default_str();
  return {app, [o] { return runSample(*o); }};
}

}  // namespace glossy::cli
