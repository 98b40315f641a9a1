// The number options of glossy's jobs, declared once: their name, range, default and help feed the command
// line's options (renderer/cli/command.h, addOption), the Python module's keyword checks
// (renderer/python/module_support.h), the EXR metadata and a sheet's settings line, which glossy sheets
// resumes by (sheet_job.cpp), and the table of docs/rendering.md ("Limits of the command line"), which
// tests/option_specs_test.cpp checks against this one.
#pragma once

#include "renderer/image/exr_image.h"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace glossy {
struct RenderSettings;
}

namespace glossy::app {

struct OptionSpec {
  std::string_view name;      // --NAME on the command line; Python's keyword is NAME with '_' for '-'
  std::string_view commands;  // the commands that take it, as the docs name them
  bool whole;                 // a whole number, else any finite number
  double lo, hi;
  bool loOpen;                // (lo, hi] rather than [lo, hi]
  double fallback;            // the default: the settings struct's own, read from it
  std::string help;
  std::string_view attribute;  // its glossy:* attribute in the EXR, "" if none
  std::string_view resumeKey;  // its KEY= in a sheet's settings line, "" if not part of it

  std::string flag() const;     // --max-depth (-n for a one-letter name)
  std::string keyword() const;  // max_depth
  std::string range() const;    // "[1, 1000]", "(0, 1e+06]"
  bool accepts(double value) const;
  // Why `text` is refused: "must be a whole number in [1, 1000], not '0'", the same words on the command
  // line (after the option) and in Python (after the keyword).
  std::string refusal(std::string_view text) const;
};

// Threads a job may be asked for: far beyond any machine's cores, well short of what exhausts memory
// creating them (`--threads 1e8`).
inline constexpr int kMaxThreads = 4096;

namespace options {
// glossy render and glossy.render()
extern const OptionSpec kSpp, kWidth, kHeight;
// glossy sheet, sheets and glossy.sheet()
extern const OptionSpec kSheetSpp, kSheetWidth, kSheetHeight, kTime, kTargetError, kExposure;
// both
extern const OptionSpec kSeed, kThreads, kMaxDepth, kLightSamples, kEnvRotate;
// glossy fit and glossy.fit(); glossy sample -n and glossy.uniforms()
extern const OptionSpec kStarts, kMaxIterations, kSamples;
}  // namespace options

// An option bound to the field of a job it sets: one list of them serves the command line's options, Python's
// keywords and a study file's settings.
struct OptionField {
  const OptionSpec* spec;
  std::variant<int*, uint32_t*, double*> field;

  void set(double value) const {
    std::visit([value](auto* f) { *f = std::remove_pointer_t<decltype(f)>(value); }, field);
  }
};

struct SheetJob;
// glossy render's (--spp, --width, --height, then the path tracer's: --seed, --threads, --max-depth,
// --light-samples) and glossy sheet's (--spp, --time, --target-error, --width, --height, the path tracer's,
// --exposure), in the order --help lists them.
std::vector<OptionField> renderOptionFields(RenderSettings& s);
std::vector<OptionField> sheetOptionFields(SheetJob& job);

// --seed's attribute: EXR has no unsigned one, so a seed beyond int's range is written as its decimal text.
ImageAttribute seedAttribute(uint32_t seed);

// Every spec above, in the docs table's order.
std::span<const OptionSpec* const> optionSpecs();
// That table in Markdown, as docs/rendering.md holds it.
std::string optionTable();

}  // namespace glossy::app
