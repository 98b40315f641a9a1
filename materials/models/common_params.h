// Parameter declarations several models share, so that their meaning and bounds are written once.
#pragma once

#include "materials/models/param_set.h"

namespace glossy::params {

// The ranges reach beyond the fitter's (below) and every published fit, and stop where a model's arithmetic
// would overflow or lose its lobe: scales up to 1e6 keep radiance finite in float even times the sharpest
// lobe's peak.
inline constexpr ParamRange kScaleRange{0.0, 1e6};
inline constexpr ParamSpec kKd{"kd", ParamKind::Rgb, kScaleRange, "diffuse albedo Kd (R, G, B)"};
inline constexpr ParamSpec kEta{"eta", ParamKind::Scalar, {1.0 + 1e-6, 1e3}, "index of refraction of the Fresnel factor"};
// The ABC lobe S(f) = A / (1 + B f²)^C of the Smooth and Microfacet models.
inline constexpr ParamSpec kAbcA{"a", ParamKind::Rgb, kScaleRange, "specular scale A (R, G, B)"};
inline constexpr ParamSpec kAbcB{"b", ParamKind::Scalar, {0.0, 1e9}, "lobe sharpness B"};
inline constexpr ParamSpec kAbcC{"c", ParamKind::Scalar, {1e-3, 100.0}, "lobe fall-off exponent C"};
inline constexpr ParamSpec kKs{"ks", ParamKind::Rgb, kScaleRange, "specular scale Ks (R, G, B)"};


// Their ranges and coarse-scan starts in the fitter. The bounds reach beyond every published fit
// (B up to 8.1e6, C down to 0.014, η up to 99.999, m down to 0.0018, n up to 6.2e5).
inline constexpr double kEtaStarts[] = {1.5, 4.0, 30.0};
inline constexpr ShapeParam kFitEta{"eta", FitScale::AboveOne, 1.0 + 1e-4, 100.0, kEtaStarts};
inline constexpr double kAbcBStarts[] = {1.0, 10.0, 100.0, 1e3, 1e4, 1e5, 1e6, 1e7};
inline constexpr ShapeParam kFitAbcB{"b", FitScale::Log, 1e-3, 1e9, kAbcBStarts};
inline constexpr double kAbcCStarts[] = {0.1, 0.5, 1.5};
inline constexpr ShapeParam kFitAbcC{"c", FitScale::Log, 1e-3, 100.0, kAbcCStarts};

}  // namespace glossy::params
