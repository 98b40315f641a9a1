"""The Microfacet model of ../shared/spec/models.md section 2 (Loew et al.'s ABC microfacet model) as a
Mitsuba 3 BSDF written in Python, sampled exactly as glossy samples it.

    rho = Kd/pi + A S(x) F(<V,H>; eta) G / (pi <L,N> <V,N>),   S(x) = (1 + B x)^(-C),   x = 1 - <N,H>

F and G as in cook_torrance.py (Fresnel at <V,H>, the V-groove G); rho = 0 unless L_z > 0 and V_z > 0.
x is formed without cancellation (cook_torrance.HalfVector), x = |h_p|^2 / (|h| (|h| + h_z)), since B
reaches 2.2e5 (aluminium's E2 fit: the lobe is a few milliradians wide with a heavy (1 + Bx)^-C tail).

Sampling is glossy's one-sample mixture (materials/models/microfacet.h, abc_profile.h, brdf_sample.h): with
probability p_spec = clamp(a_s / (a_s + mean Kd), 0.05, 0.95), a_s = 8 mean(A) F(1; eta) I(1 - sqrt(1/2)),
I(s) = integral of S over [0, s], x is drawn with density S(x) / I(1) on [0, 1] by inverting I, phi_h
uniform, L = reflect(V, H); otherwise L is drawn from the cosine lobe. pdf() is the mixture density
p_spec S(x) / (2 pi I(1) 4 <V,H>) + (1 - p_spec) cos th_L / pi. The constants (p_spec, I(1), and the
inversion's expm1((1 - C) log1p(B))) are computed here in double once.

Float32 per lane, as Mitsuba's variant is. Dr.Jit has no log1p or expm1, so they are formed with the
classic correction (log(u) y / (u - 1) with u = 1 + y; (u - 1) w / log(u) with u = exp(w)), which keeps
full relative precision for small arguments where log(1 + y) and exp(w) - 1 would cancel.
"""

import math

import drjit as dr
import mitsuba as mi

from cook_torrance import HalfVector, MixtureBSDF, fresnel_cook_torrance, fresnel_scalar, lobe_probability


def log1p(y):
    """log(1 + y) for y > -1 without cancellation near 0."""
    u = 1.0 + y
    d = u - 1.0
    return dr.select(d == 0.0, y, dr.log(u) * (y / dr.select(d == 0.0, 1.0, d)))


def expm1(w):
    """exp(w) - 1 without cancellation near 0."""
    u = dr.exp(w)
    d = u - 1.0
    lu = dr.log(u)
    return dr.select(d == 0.0, w, dr.select(u == 0.0, -1.0, d * (w / dr.select(lu == 0.0, 1.0, lu))))


class AbcProfile:
    """s -> (1 + B s)^-C, its integral over [0, s] and the inverse of that, as abc_profile.h (scalars in
    double, lanes in float32)."""

    def __init__(self, b, c):
        self.b, self.c = float(b), float(c)

    def integral(self, s):
        bs = self.b * s
        if bs < 1e-12:
            return s
        l, k = math.log1p(bs), 1.0 - self.c
        if abs(k * l) < 1e-10:
            return l / self.b
        return math.expm1(k * l) / (k * self.b)

    def value(self, x):
        return dr.exp(-self.c * log1p(self.b * x))

    def invert_unit(self, xi):
        """The x in [0, 1] whose integral is xi I(1)."""
        b, k = self.b, 1.0 - self.c
        if b < 1e-12:
            return xi
        l_max = math.log1p(b)
        if abs(k * l_max) < 1e-10:
            return expm1(xi * l_max) / b
        # (1 + B x)^(1 - C) = 1 + xi ((1 + B)^(1 - C) - 1)
        return expm1(log1p(xi * math.expm1(k * l_max)) / k) / b


class MicrofacetBSDF(MixtureBSDF):
    def __init__(self, props):
        MixtureBSDF.__init__(self, props)
        self.kd = [props["kd_r"], props["kd_g"], props["kd_b"]]
        self.a = [props["a_r"], props["a_g"], props["a_b"]]
        self.eta = float(props["eta"])
        self.profile = AbcProfile(props["b"], props["c"])
        self.norm = 1.0 / (self.profile.integral(1.0) * 2.0 * math.pi * 4.0)
        # glossy's specularProbability(): head-on lobe albedo ~ 8 A F(1) I(1 - sqrt(1/2)) (G ~ 1).
        head_on = self.profile.integral(1.0 - math.sqrt(0.5))
        specular = 8.0 * (sum(self.a) / 3.0) * fresnel_scalar(1.0, self.eta) * head_on
        self.p_spec = lobe_probability(specular, self.kd)

    # rho(L, V) * L_z and the mixture pdf, sharing the half-vector terms.
    def _eval_pdf(self, V, L, active):
        h = HalfVector(V, L)
        s = self.profile.value(h.one_minus_cos)
        f = fresnel_cook_torrance(h.cos_vh, self.eta)
        valid = active & (L.z > 0.0) & (V.z > 0.0)
        # (Kd/pi + A S F G / (pi L_z V_z)) * L_z
        value = mi.Color3f(self.kd) * (L.z / dr.pi) + mi.Color3f(self.a) * (s * f * h.g / (dr.pi * V.z))
        lobe_pdf = dr.select(h.cos_vh > 0.0, s * self.norm / h.cos_vh, 0.0)
        pdf = self.p_spec * lobe_pdf + (1.0 - self.p_spec) * L.z / dr.pi
        return dr.select(valid, value, 0.0), dr.select(valid, pdf, 0.0)

    def sample_direction(self, V, sample1, sample2):
        specular = sample1 < self.p_spec
        x = self.profile.invert_unit(sample2.x)
        cos_t = 1.0 - x
        sin_t = dr.sqrt(dr.maximum(0.0, x * (2.0 - x)))
        sin_p, cos_p = dr.sincos(2.0 * dr.pi * sample2.y)
        H = mi.Vector3f(sin_t * cos_p, sin_t * sin_p, cos_t)
        vh = dr.dot(V, H)
        L = dr.select(specular, 2.0 * vh * H - V, mi.warp.square_to_cosine_hemisphere(sample2))
        return L, specular, ~specular | (vh > 0.0)

    def to_string(self):
        return (f"MicrofacetBSDF[kd={self.kd}, a={self.a}, b={self.profile.b}, c={self.profile.c}, "
                f"eta={self.eta}, p_spec={self.p_spec:.4f}]")


def register():
    mi.register_bsdf("glossy_microfacet", lambda props: MicrofacetBSDF(props))


def bsdf_dict(fit):
    """Scene-dictionary entry for a microfacet fit {kd: [r,g,b], a: [r,g,b], b, c, eta}."""
    d = {"type": "glossy_microfacet", "b": float(fit["b"]), "c": float(fit["c"]), "eta": float(fit["eta"])}
    for name in ("kd", "a"):
        for channel, value in zip("rgb", fit[name]):
            d[f"{name}_{channel}"] = float(value)
    return d
