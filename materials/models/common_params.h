// Parameter declarations several models share, so that their meaning and bounds are written once.
#pragma once

#include "materials/params/param_set.h"

namespace glossy::params {

inline constexpr ParamSpec kKd{"kd", ParamKind::Rgb, ParamBound::NonNegative, "diffuse albedo Kd (R, G, B)"};
inline constexpr ParamSpec kEta{"eta", ParamKind::Scalar, ParamBound::AboveOne,
                                "index of refraction of the Fresnel factor"};
// The ABC lobe S(f) = A / (1 + B f²)^C of the Smooth and Microfacet models.
inline constexpr ParamSpec kAbcA{"a", ParamKind::Rgb, ParamBound::NonNegative, "specular scale A (R, G, B)"};
inline constexpr ParamSpec kAbcB{"b", ParamKind::Scalar, ParamBound::NonNegative, "lobe sharpness B"};
inline constexpr ParamSpec kAbcC{"c", ParamKind::Scalar, ParamBound::Positive, "lobe fall-off exponent C"};
inline constexpr ParamSpec kKs{"ks", ParamKind::Rgb, ParamBound::NonNegative, "specular scale Ks (R, G, B)"};

}  // namespace glossy::params
