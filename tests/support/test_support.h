// Helpers shared by the tests: where the reference data is, running the glossy command, temporary
// folders, and writing synthetic MERL-format tables.
#pragma once

#include "materials/core/types.h"
#include "materials/merl/merl_table.h"
#include "materials/models/brdf.h"
#include "materials/params/material_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace glossy::test {

// ../shared beside the checkout ($GLOSSY_SHARED_DIR overrides).
std::filesystem::path sharedDir();
std::filesystem::path sourceDir();
// The committed library, a folder per database (materials/library), and its MERL folder, where the
// 100 MERL materials' parameter files and networks are.
std::filesystem::path libraryDir();
std::filesystem::path materialsDir();
// The six materials of Löw et al. 2012's supplement, sorted: the library's MERL files whose source is the
// supplement (materials/params/importer.h), which shared/merl holds the tables of.
const std::vector<std::string>& supplementMaterials();

// Skips the calling test, with a message naming the folder, when shared/<sub> is absent.
#define GLOSSY_REQUIRE_SHARED(sub)                                                                       \
  do {                                                                                                   \
    if (!std::filesystem::exists(::glossy::test::sharedDir() / (sub)))                                   \
      GTEST_SKIP() << "reference data " << (::glossy::test::sharedDir() / (sub)).string() << " is absent"; \
  } while (0)

struct RunResult {
  int status = -1;
  std::string out, err;
};
// Runs the glossy executable with `args` (shell-quoted here) and `input` on stdin.
RunResult runGlossy(const std::vector<std::string>& args, const std::string& input = "");
// `s` as one word for /bin/sh: in single quotes, each ' written '\''.
std::string shellQuote(const std::string& s);
// The same, run in folder `cwd` with the environment variables `unset` removed.
RunResult runGlossyIn(const std::filesystem::path& cwd, const std::vector<std::string>& unset, const std::vector<std::string>& args);

// Runs f, which must throw InputError with a one-line message; returns the message.
std::string expectInputError(const std::function<void()>& f);
// A glossy run that must fail as bad input: exit status 2, nothing on stdout, one line on stderr that
// mentions `mention`.
void expectOneLineError(const RunResult& r, const std::string& mention);

class TempDir {
 public:
  TempDir();
  ~TempDir();
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

void writeText(const std::filesystem::path& path, const std::string& text);
std::string readText(const std::filesystem::path& path);

// Rows of a CSV file with a header line, as maps from column name to text.
std::vector<std::map<std::string, std::string>> readCsv(const std::filesystem::path& path);
// Every src=, href=, data-src= and data-measured-src= of an HTML page, as written.
std::vector<std::string> htmlReferences(const std::string& html);

// The bytes of a MERL .binary whose stored (unscaled) value at bin (θh, θd, φd) is f(θh, θd, φd).
using MerlFiller = std::function<Rgb(int thetaH, int thetaD, int phiD)>;
std::string syntheticMerlBytes(const MerlFiller& f);

// L and V (local frame) with the given half/difference angles; φ_h rotates the pair about N.
std::pair<Vec3, Vec3> fromHalfDiff(double thetaH, double thetaD, double phiD, double phiH = 0.0);

// The bytes of a MERL table holding an analytic BRDF at the centre of every bin, stored as the reference
// reader expects (÷ the channel scale); `unmeasured(θh, θd, φd)` marks bins as negative (invalid).
using BinPredicate = std::function<bool(int thetaH, int thetaD, int phiD)>;
std::string tabulatedMerlBytes(const Brdf& brdf, const BinPredicate& unmeasured = {});
// The same, parsed.
std::shared_ptr<const MerlTable> tabulateMerl(const Brdf& brdf, const BinPredicate& unmeasured = {});

// A validated fit of `model` under `metric` with the given parameter values (fitting round trips).
Fit makeFit(const std::string& model, const std::string& metric,
            const std::vector<std::pair<std::string, ParamSet::Value>>& values);
// The lobe's width as the round trips judge it: m (CT), n^−½ (AS), or for the ABC models the half-width
// sqrt((2^{1/C} − 1)/B) at which (1 + B f²)^(−C) falls to half its peak.
double lobeWidth(const Fit& fit);

}  // namespace glossy::test
