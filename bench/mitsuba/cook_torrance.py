"""Cook-Torrance of ../shared/spec/models.md section 3 as a Mitsuba 3 BSDF written in Python.

    rho = Kd/pi + Ks * D * F(<V,H>; eta) * G / (pi <L,N> <V,N>),   D = exp(-tan^2 th_h / m^2) / (m^2 cos^4 th_h)

D is Beckmann without its 1/pi (that 1/pi sits in the denominator, the spec's convention); F is the
unpolarised dielectric Fresnel factor of Cook & Torrance at c = <V,H>; G the V-groove term
min(1, 2<N,H><N,V>/<V,H>, 2<N,H><N,L>/<V,H>), 0 for <V,H> <= 0. rho = 0 unless L_z > 0 and V_z > 0.
Half-vector quantities are formed without cancellation, as the spec asks: with h = L + V,
tan^2 th_h = |h_p|^2 / h_z^2.

Sampling is glossy's one-sample mixture (materials/models/brdf_sample.h, cook_torrance.h): with probability
p_spec = clamp(a_s / (a_s + mean Kd), 0.05, 0.95), a_s = 4 mean(Ks) F(1; eta), the half vector is drawn
from Beckmann (tan^2 th_h = -m^2 ln(1 - xi1), phi = 2 pi xi2) and L = reflect(V, H); otherwise L is drawn
from the cosine lobe (Malley's method on the concentric disk). pdf() is the mixture density
p_spec * pdf_h / (4 <V,H>) + (1 - p_spec) cos th_L / pi, exactly what sample() draws from; a direction
below the horizon is an invalid sample (no renormalisation).

In Mitsuba's terms: si.wi is V, wo is L (both in the local shading frame); eval() returns rho * cos th_L
and sample() returns rho * cos th_L / pdf. In a JIT (llvm_ad_*) variant these methods are traced once and
compiled into the integrator's kernel like any built-in BSDF. Float32 throughout, as Mitsuba's variant is.
"""

import math

import drjit as dr
import mitsuba as mi


def fresnel_cook_torrance(c, eta):
    """Spec: g = sqrt(eta^2 + c^2 - 1), F = 1/2 ((g-c)/(g+c))^2 [1 + ((c(g+c) - 1)/(c(g-c) + 1))^2]."""
    c = dr.clip(c, 0.0, 1.0)
    g = dr.sqrt(dr.maximum(eta * eta + c * c - 1.0, 0.0))
    a = (g - c) / (g + c)
    b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0)
    return 0.5 * a * a * (1.0 + b * b)


def fresnel_scalar(c, eta):
    g = math.sqrt(max(eta * eta + c * c - 1.0, 0.0))
    a = (g - c) / (g + c)
    b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0)
    return 0.5 * a * a * (1.0 + b * b)


def lobe_probability(specular, kd):
    """glossy's lobeProbability() (brdf_sample.h): the specular lobe's share from the lobes' approximate
    albedos (the diffuse one the mean of Kd), clamped to [0.05, 0.95] while both lobes have some albedo."""
    diffuse = sum(kd) / 3.0
    if not specular > 0.0:
        return 0.0
    if not diffuse > 0.0:
        return 1.0
    return min(max(specular / (specular + diffuse), 0.05), 0.95)


class HalfVector:
    """The half-vector terms of a direction pair (V, L), both with z > 0, formed from h = L + V without
    cancellation (glossy's half_vector.h, vgroove.h): cos th_h, 1 - cos th_h = |h_p|^2 / (|h| (|h| + h_z)),
    tan^2 th_h = |h_p|^2 / h_z^2, <V,H>, and the V-groove G (0 for <V,H> <= 0). Terms a model does not use
    cost nothing: Dr.Jit compiles only what the outputs need."""

    def __init__(self, V, L):
        h = V + L
        p2 = h.x * h.x + h.y * h.y
        length = dr.sqrt(p2 + h.z * h.z)
        self.cos = h.z / length
        self.one_minus_cos = p2 / (length * (length + h.z))
        self.tan2 = p2 / (h.z * h.z)
        self.cos_vh = dr.dot(V, h) / length
        s = 2.0 * self.cos / self.cos_vh
        self.g = dr.select(self.cos_vh > 0.0, dr.minimum(1.0, dr.minimum(s * V.z, s * L.z)), 0.0)


class MixtureBSDF(mi.BSDF):
    """What glossy's one-sample mixtures share in Mitsuba: a subclass gives _eval_pdf(V, L, active), the
    value rho * L_z and the mixture density, and sample_direction(V, sample1, sample2), the direction
    drawn, whether from the specular lobe, and whether the lobe's draw is usable."""

    def __init__(self, props):
        mi.BSDF.__init__(self, props)
        self.m_flags = mi.BSDFFlags.GlossyReflection | mi.BSDFFlags.DiffuseReflection | mi.BSDFFlags.FrontSide
        self.m_components = [mi.BSDFFlags.GlossyReflection | mi.BSDFFlags.FrontSide,
                             mi.BSDFFlags.DiffuseReflection | mi.BSDFFlags.FrontSide]

    def eval(self, ctx, si, wo, active=True):
        return self._eval_pdf(si.wi, wo, active)[0]

    def pdf(self, ctx, si, wo, active=True):
        return self._eval_pdf(si.wi, wo, active)[1]

    def eval_pdf(self, ctx, si, wo, active=True):
        return self._eval_pdf(si.wi, wo, active)

    def sample(self, ctx, si, sample1, sample2, active=True):
        V = si.wi
        L, specular, lobe_ok = self.sample_direction(V, sample1, sample2)
        value, pdf = self._eval_pdf(V, L, active)
        return make_sample(L, specular, active & lobe_ok & (V.z > 0.0) & (L.z > 0.0), value, pdf)

    def traverse(self, callback):
        pass

    def parameters_changed(self, keys):
        pass


class CookTorranceBSDF(MixtureBSDF):
    def __init__(self, props):
        MixtureBSDF.__init__(self, props)
        self.kd = [props["kd_r"], props["kd_g"], props["kd_b"]]
        self.ks = [props["ks_r"], props["ks_g"], props["ks_b"]]
        self.m = float(props["m"])
        self.eta = float(props["eta"])
        self.p_spec = lobe_probability(4.0 * (sum(self.ks) / 3.0) * fresnel_scalar(1.0, self.eta), self.kd)

    # rho(L, V) * L_z and the mixture pdf, sharing the half-vector terms.
    def _eval_pdf(self, V, L, active):
        m2 = self.m * self.m
        h = HalfVector(V, L)
        e = dr.exp(-h.tan2 / m2)
        cos2 = h.cos * h.cos
        d = e / (m2 * cos2 * cos2)
        f = fresnel_cook_torrance(h.cos_vh, self.eta)
        valid = active & (L.z > 0.0) & (V.z > 0.0)
        # (Kd/pi + Ks D F G / (pi L_z V_z)) * L_z
        spec = d * f * h.g / (dr.pi * V.z)
        value = mi.Color3f(self.kd) * (L.z / dr.pi) + mi.Color3f(self.ks) * spec
        lobe_pdf = dr.select(h.cos_vh > 0.0, e / (dr.pi * m2 * cos2 * h.cos * 4.0 * h.cos_vh), 0.0)
        pdf = self.p_spec * lobe_pdf + (1.0 - self.p_spec) * L.z / dr.pi
        return dr.select(valid, value, 0.0), dr.select(valid, pdf, 0.0)

    def sample_direction(self, V, sample1, sample2):
        """L drawn from the mixture (also the measured plugin's proposal): (L, specular lobe?, lobe ok)."""
        specular = sample1 < self.p_spec
        # Beckmann half vector: 1 - cos th = tan^2 / (sec (sec + 1)), no cancellation.
        tan2 = -self.m * self.m * dr.log(1.0 - sample2.x)
        sec = dr.sqrt(1.0 + tan2)
        one_minus_cos = tan2 / (sec * (sec + 1.0))
        cos_t = 1.0 - one_minus_cos
        sin_t = dr.sqrt(dr.maximum(0.0, one_minus_cos * (2.0 - one_minus_cos)))
        sin_p, cos_p = dr.sincos(2.0 * dr.pi * sample2.y)
        H = mi.Vector3f(sin_t * cos_p, sin_t * sin_p, cos_t)
        vh = dr.dot(V, H)
        L_spec = 2.0 * vh * H - V
        L_diff = mi.warp.square_to_cosine_hemisphere(sample2)
        return dr.select(specular, L_spec, L_diff), specular, ~specular | (vh > 0.0)

    def to_string(self):
        return f"CookTorranceBSDF[kd={self.kd}, ks={self.ks}, m={self.m}, eta={self.eta}, p_spec={self.p_spec:.4f}]"


def make_sample(L, specular, valid, value, pdf):
    """Mitsuba's (BSDFSample3f, weight) for a direction L drawn by the mixture: weight = value / pdf, both 0
    where the sample is invalid or its density is not a positive finite number."""
    valid = valid & (pdf > 0.0) & dr.isfinite(pdf)
    bs = dr.zeros(mi.BSDFSample3f)
    bs.wo = L
    bs.pdf = dr.select(valid, pdf, 0.0)
    bs.eta = 1.0
    bs.sampled_type = dr.select(specular, mi.UInt32(+mi.BSDFFlags.GlossyReflection),
                                mi.UInt32(+mi.BSDFFlags.DiffuseReflection))
    bs.sampled_component = dr.select(specular, mi.UInt32(0), mi.UInt32(1))
    return bs, dr.select(valid, value / pdf, 0.0)


def register():
    mi.register_bsdf("glossy_cook_torrance", lambda props: CookTorranceBSDF(props))


def bsdf_dict(fit):
    """Scene-dictionary entry for a cook-torrance fit {kd: [r,g,b], ks: [r,g,b], m, eta}."""
    d = {"type": "glossy_cook_torrance", "m": float(fit["m"]), "eta": float(fit["eta"])}
    for name in ("kd", "ks"):
        for channel, value in zip("rgb", fit[name]):
            d[f"{name}_{channel}"] = float(value)
    return d
