// The data-quality figures of Neural BRDF networks (bench/network_quality.h; docs/measured.md, "Data
// quality"): one line per .nbrdf (with --markdown, a table row per network that trips a criterion), then
// one per database (the networks' labels) counting the networks that trip each criterion.
//   build/bench/nbrdf_quality --markdown materials/library/*/*.nbrdf
#include "bench/network_quality.h"
#include "materials/core/input_error.h"
#include "materials/core/text.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>

using namespace glossy;
using namespace glossy::bench;

namespace {

// The criteria of docs/measured.md.
constexpr double kNegativeShare = 1e-3;  // of the measured bins, in any channel
constexpr double kNegativeValue = -0.05; // 1/sr, in any bin
constexpr double kAlbedo = 1.0;
constexpr double kAsymmetryRms = 0.2;

struct Flags {
  bool negative, nonFinite, albedo, asymmetric;
  bool any() const { return negative || nonFinite || albedo || asymmetric; }
};

Flags flagsOf(const NetworkQuality& q) {
  bool negative = false;
  for (int c = 0; c < 3; ++c) negative = negative || q.negativeShare(c) > kNegativeShare || q.lowest[size_t(c)] < kNegativeValue;
  return {negative, q.nonFiniteBins > 0, q.maxAlbedo > kAlbedo, q.asymmetryRms > kAsymmetryRms};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"nbrdf_quality: how plausible each Neural BRDF network's values are (docs/measured.md, Data quality)"};
  std::vector<std::string> files;
  bool markdown = false;
  app.add_option("files", files, "Neural BRDF files (.nbrdf)")->required();
  app.add_flag("--markdown", markdown, "Only the networks that trip a criterion, as docs/measured.md's table");
  CLI11_PARSE(app, argc, argv);

  // Every file is read before any is assessed: a bad one is refused before the work starts.
  std::vector<NeuralBrdf> networks;
  try {
    for (const std::string& file : files) networks.push_back(NeuralBrdf::load(file));
  } catch (const InputError& e) {
    std::fprintf(stderr, "nbrdf_quality: %s\n", e.what());
    return 2;
  }

  if (markdown)
    std::printf("| material | database | ρ̄ < 0: share of bins R / G / B | lowest ρ̄ (1/sr) | max albedo (θ_V) | asymmetry RMS / max | "
                "criteria |\n|---|---|---|---|---|---|---|\n");
  else
    std::printf("%-32s %-10s %8s %8s %8s %10s %10s %10s %6s %7s %3s %5s %7s %7s %s\n", "material", "database", "neg R %",
                "neg G %", "neg B %", "lowest R", "lowest G", "lowest B", "nonfin", "albedo", "ch", "θv", "asymRMS",
                "asymMax", "flags");
  struct Count {
    int networks = 0, negative = 0, nonFinite = 0, albedo = 0, asymmetric = 0, any = 0;
  };
  std::map<std::string, Count> databases;
  for (const NeuralBrdf& n : networks) {
    const NetworkQuality q = assessNetwork(n, n.tabulate());
    const Flags f = flagsOf(q);
    const std::string database = n.label().substr(0, n.label().find(" (")), lowest = std::min({q.lowest[0], q.lowest[1], q.lowest[2]}) < 0.0
        ? formatted("%.3g / %.3g / %.3g", q.lowest[0], q.lowest[1], q.lowest[2]) : "–";
    const std::string flags = std::string(f.negative ? "negative, " : "") + (f.nonFinite ? "non-finite, " : "") +
                              (f.albedo ? "albedo > 1, " : "") + (f.asymmetric ? "non-reciprocal, " : "");
    if (markdown && f.any())
      std::printf("| %s | %s | %.3f %% / %.3f %% / %.3f %% | %s | %.3f %c (%.0f°) | %.2f / %.3g | %s%s |\n", n.material().c_str(),
                  database.c_str(), 100.0 * q.negativeShare(0), 100.0 * q.negativeShare(1), 100.0 * q.negativeShare(2),
                  lowest.c_str(), q.maxAlbedo, "RGB"[q.maxAlbedoChannel], q.maxAlbedoThetaVDeg, q.asymmetryRms, q.asymmetryMax,
                  flags.substr(0, flags.size() - 2).c_str(), q.nonFiniteBins ? formatted(" (%zu bins)", q.nonFiniteBins).c_str() : "");
    else if (!markdown)
      std::printf("%-32s %-10s %8.4f %8.4f %8.4f %10.4g %10.4g %10.4g %6zu %7.4f %3c %5.0f %7.4f %7.3g %s\n", n.material().c_str(),
                  database.c_str(), 100.0 * q.negativeShare(0), 100.0 * q.negativeShare(1), 100.0 * q.negativeShare(2),
                  q.lowest[0], q.lowest[1], q.lowest[2], q.nonFiniteBins, q.maxAlbedo, "RGB"[q.maxAlbedoChannel],
                  q.maxAlbedoThetaVDeg, q.asymmetryRms, q.asymmetryMax, flags.substr(0, flags.size() - (flags.empty() ? 0 : 2)).c_str());
    std::fflush(stdout);
    Count& c = databases[n.label()];
    ++c.networks;
    c.negative += f.negative, c.nonFinite += f.nonFinite, c.albedo += f.albedo, c.asymmetric += f.asymmetric, c.any += f.any();
  }
  std::printf("\ncriteria: ρ̄ < 0 in more than %g %% of the measured bins of a channel or below %g 1/sr; any non-finite value; "
              "albedo > %g; asymmetry RMS > %g\n\n",
              100.0 * kNegativeShare, kNegativeValue, kAlbedo, kAsymmetryRms);
  for (const auto& [label, c] : databases)
    std::printf("%s%s: %d networks, %d trip a criterion (negative %d, non-finite %d, albedo > 1 %d, non-reciprocal %d)\n",
                markdown ? "- " : "", label.c_str(), c.networks, c.any, c.negative, c.nonFinite, c.albedo, c.asymmetric);
}
