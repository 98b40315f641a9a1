// The built-in analytic models: the one list of them, in the order of the supplement's comparison grid
// (Microfacet, Smooth, Ashikhmin-Shirley, Cook-Torrance), then Lambertian, then the models added since, in the
// order they were (appended, so that the fits already in a parameter file keep their order). The registry (registry.cpp)
// lists them from it at run time; the fitter (fitter.cpp) needs their static types, for Ceres' jets, and
// instantiates itself for each. A new model is its header and one entry here.
#pragma once

#include "materials/models/ashikhmin_shirley.h"
#include "materials/models/cook_torrance.h"
#include "materials/models/ggx.h"
#include "materials/models/blinn_phong.h"
#include "materials/models/lafortune.h"
#include "materials/models/lambertian.h"
#include "materials/models/microfacet.h"
#include "materials/models/ngan_ashikhmin_shirley.h"
#include "materials/models/ngan_cook_torrance.h"
#include "materials/models/sgd.h"
#include "materials/models/smooth.h"
#include "materials/models/ward.h"
#include "materials/models/ward_duer.h"

namespace glossy {

template <class... Models>
struct ModelList {};

using BuiltinModels = ModelList<Microfacet, Smooth, AshikhminShirley, CookTorrance, Lambertian, Ggx, Ward, WardDuer,
                           BlinnPhong, Lafortune, NganAshikhminShirley, NganCookTorrance, Sgd>;

}  // namespace glossy
