#include "renderer/app/option_specs.h"

#include "materials/core/text.h"
#include "materials/fitting/fitter.h"
#include "renderer/app/sheet_job.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <memory>

namespace glossy::app {

namespace options {

namespace {
const RenderSettings kRender{};
const SheetSettings kSheet{};
const FitSettings kFit{};
const std::string kCap = std::to_string(kTargetErrorSppCap);
}  // namespace

const OptionSpec kSpp{"spp", "render", true, 1, INT32_MAX, false, double(kRender.spp), "Samples per pixel", "glossy:spp", ""};
const OptionSpec kWidth{"width", "render", true, 1, 1 << 15, false, double(kRender.width), "Image width", "", ""};
const OptionSpec kHeight{"height", "render", true, 1, 1 << 15, false, double(kRender.height), "Image height", "", ""};
const OptionSpec kSheetSpp{"spp", "sheet, sheets", true, 1, 1 << 24, false, double(kSheet.spp), "Samples per pixel of every panel, in 4 independent replicates (rounded up to a multiple of 4); with --target-error or --time: at most this many (--target-error alone: at most " + kCap + ")", "glossy:spp", "spp"};
// A sheet's settings line gives the panel size as size=WxH.
const OptionSpec kSheetWidth{"width", "sheet, sheets", true, 8, 1 << 14, false, double(kSheet.width), "Panel width", "", "size"};
const OptionSpec kSheetHeight{"height", "sheet, sheets", true, 8, 1 << 14, false, double(kSheet.height), "Panel height", "", "size"};
const OptionSpec kTime{"time", "sheet, sheets", false, 0, 1e6, true, kSheet.secondsPerPanel, "Wall-clock seconds per panel instead of --spp: the panels render in passes until their budget is spent", "glossy:secondsPerPanel", "time"};
const OptionSpec kTargetError{"target-error", "sheet, sheets", false, 0, 10, true, kSheet.targetError, "Render in passes until every model's relative-RMSE 95 % interval has at most this half-width, or until --spp (default " + kCap + ") or --time caps it, saying so; a line per pass on stderr", "glossy:targetError", "targetError"};
const OptionSpec kExposure{"exposure", "sheet, sheets", false, -64, 64, false, std::make_unique<const SheetJob>()->exposure, "Exposure of the PNG preview in stops (the EXR stays linear)", "glossy:pngExposure", "exposure"};
const OptionSpec kSeed{"seed", "render, sheet, sheets", true, 0, 4294967295.0, false, double(kRender.seed), "Random seed (a sheet's panels share it)", "glossy:seed", "seed"};
const OptionSpec kThreads{"threads", "render, sheet, sheets, study, fit", true, 0, kMaxThreads, false, double(kRender.threads), "Threads (0 = all cores)", "", ""};
const OptionSpec kMaxDepth{"max-depth", "render, sheet, sheets", true, 1, 1000, false, double(kRender.maxDepth), "Path segments at most (1 = emitters only, 3 = one indirect bounce)", "glossy:maxDepth", "maxDepth"};
const OptionSpec kLightSamples{"light-samples", "render, sheet, sheets", true, 1, kMaxLightSamples, false, double(kRender.lightSamples), "Light samples at a path's first vertex, at most: each BRDF takes its own count, fewer for sharper lobes (more: less noise from the lights at less than a path's cost)", "glossy:lightSamples", "lightSamples"};
// The environment's rotation reaches a sheet's settings line through its description (env=).
const OptionSpec kEnvRotate{"env-rotate", "render, sheet, sheets", false, -360, 360, false, 0.0, "Rotate the environment about +Y, degrees", "", ""};
const OptionSpec kStarts{"starts", "fit", true, 1, 64, false, double(kFit.refinedStarts), "Lobe widths refined from the coarse scan", "", ""};
const OptionSpec kMaxIterations{"max-iterations", "fit", true, 1, 10000, false, double(kFit.maxIterations), "Levenberg-Marquardt iterations per start", "", ""};
const OptionSpec kSamples{"n", "sample", true, 0, 1e9, false, 0, "Number of samples", "", ""};

}  // namespace options

namespace {

using namespace options;
const OptionSpec* const kAll[] = {&kSpp, &kSheetSpp, &kWidth, &kHeight, &kSheetWidth, &kSheetHeight, &kTime, &kTargetError, &kExposure,
                                  &kSeed, &kThreads, &kMaxDepth, &kLightSamples, &kEnvRotate, &kStarts, &kMaxIterations, &kSamples};

std::string number(bool whole, double v) { return whole ? formatted("%lld", (long long)v) : formatted("%g", v); }

}  // namespace

std::span<const OptionSpec* const> optionSpecs() { return kAll; }

std::string OptionSpec::flag() const { return (name.size() > 1 ? "--" : "-") + std::string(name); }

std::string OptionSpec::keyword() const {
  std::string k(name);
  std::replace(k.begin(), k.end(), '-', '_');
  return k;
}

std::string OptionSpec::range() const {
  return formatted("%s%s, %s]", loOpen ? "(" : "[", number(whole, lo).c_str(), number(whole, hi).c_str());
}

bool OptionSpec::accepts(double v) const {
  return std::isfinite(v) && (!whole || v == std::floor(v)) && (loOpen ? v > lo : v >= lo) && v <= hi;
}

std::string OptionSpec::refusal(std::string_view text) const {
  return std::string(whole ? "must be a whole number in " : "must be a finite number in ") + range() + ", not '" +
         shortened(std::string(text)) + "'";
}

namespace {

std::vector<OptionField> withTracerFields(std::vector<OptionField> fields, RenderSettings& s) {
  fields.insert(fields.end(), {{&kSeed, &s.seed}, {&kThreads, &s.threads}, {&kMaxDepth, &s.maxDepth}, {&kLightSamples, &s.lightSamples}});
  return fields;
}

}  // namespace

std::vector<OptionField> renderOptionFields(RenderSettings& s) {
  return withTracerFields({{&kSpp, &s.spp}, {&kWidth, &s.width}, {&kHeight, &s.height}}, s);
}

std::vector<OptionField> sheetOptionFields(SheetJob& job) {
  SheetSettings& s = job.settings;
  std::vector<OptionField> fields = withTracerFields({{&kSheetSpp, &s.spp}, {&kTime, &s.secondsPerPanel}, {&kTargetError, &s.targetError},
                                                      {&kSheetWidth, &s.width}, {&kSheetHeight, &s.height}}, s);
  fields.push_back({&kExposure, &job.exposure});
  return fields;
}

ImageAttribute seedAttribute(uint32_t seed) {
  const std::string name(options::kSeed.attribute);
  return seed <= uint32_t(INT32_MAX) ? ImageAttribute{name, int(seed)} : ImageAttribute{name, std::to_string(seed)};
}

std::string optionTable() {
  std::string out = "| option | of | accepted | default | |\n|---|---|---|---|---|\n";
  for (const OptionSpec* o : kAll)
    out += "| `" + o->flag() + "` | " + std::string(o->commands) +
           " | " + (o->whole ? "whole number in " : "") + o->range() + " | " + number(o->whole, o->fallback) + " | " + o->help + " |\n";
  return out;
}

}  // namespace glossy::app
