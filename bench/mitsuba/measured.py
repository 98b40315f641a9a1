"""A MERL-format measured BRDF table (../shared/spec/merl.md) as a Mitsuba 3 BSDF written in Python.

Evaluation is glossy's (materials/merl/merl_table.cpp): the reference nearest-lower-bin lookup in
Rusinkiewicz coordinates, no interpolation,

    i_th = floor(90 sqrt(th_h / (pi/2))),  i_td = floor(90 th_d / (pi/2)),  i_pd = floor(180 phi_d / pi)
    (phi_d < 0 folded by + pi; each clamped to the table), channel scales 1/1500, 1.15/1500, 1.66/1500,

an unmeasured bin (any channel negative) evaluating to 0, and 0 unless L_z > 0 and V_z > 0. The table is
held as float32, RGB interleaved per bin (as glossy holds it), and read with one gather per channel.
The angles are formed from the unnormalised half vector h = L + V with atan2 (th_h = atan2(|h_p|, h_z),
the difference vector's th_d likewise) rather than acos: in float32, acos near 1 resolves th_h only to
~3e-4 rad while the first th_h bin edge is at 1.9e-4 rad, so acos would put near-mirror pairs in the wrong
bin. With atan2, float32 picks glossy's (double) bin except near bin edges and within ~1e-4 rad of the mirror
direction, where phi_h (hence phi_d) turns with the float32 rounding of L and V (check_plugins.py: 5 of
2000 test pairs, all there).

Sampling is not glossy's tabulated scheme (materials/models/merl_sampling.*): Mitsuba's side samples the
material's fitted Cook-Torrance lobe as a proposal, exactly the mixture of cook_torrance.py (Beckmann half
vector with probability p_spec of the fit, else the cosine lobe), with that mixture's exact density as
pdf() and the table's value in the weight. This is what a Mitsuba user without a tabulated sampler would
reasonably do; for blue-rubber the CT E1 fit is close to the data (its ABC fits differ from the
reconstruction by a median 2-7 % below th_d = 60 deg), so the proposal follows the lobe well.
"""

import lzma
from pathlib import Path

import drjit as dr
import mitsuba as mi
import numpy as np

from cook_torrance import CookTorranceBSDF

BINS = 90 * 90 * 180
SCALE = (1.0 / 1500.0, 1.15 / 1500.0, 1.66 / 1500.0)
_tables = {}


def load_table(path):
    """(float32 array [BINS * 3] of scaled values, RGB interleaved, unmeasured bins 0; unmeasured count).
    Reads NAME.binary or NAME.binary.xz; the size and header checks of merl.md."""
    path = Path(path)
    key = str(path.resolve())
    if key not in _tables:
        raw = path.read_bytes()
        if path.suffix == ".xz":
            raw = lzma.decompress(raw)
        if len(raw) != 12 + 3 * BINS * 8 or tuple(np.frombuffer(raw[:12], "<i4")) != (90, 90, 180):
            raise ValueError(f"{path}: not a MERL table ({len(raw)} bytes)")
        data = np.frombuffer(raw[12:], "<f8").reshape(3, BINS)
        valid = (data >= 0.0).all(axis=0)
        scaled = (data.astype(np.float32).T * np.array(SCALE, np.float32)[None, :]).astype(np.float32)
        scaled[~valid] = 0.0
        _tables[key] = (np.ascontiguousarray(scaled).ravel(), int((~valid).sum()))
    return _tables[key]


def bin_index(L, V):
    """The reference lookup's flat bin index for (L, V), both with z > 0, in float32 lanes (mi.Int32)."""
    h = L + V
    hp = dr.sqrt(h.x * h.x + h.y * h.y)
    hl = dr.sqrt(hp * hp + h.z * h.z)
    theta_h = dr.atan2(hp, h.z)
    # Rotate L about z by -phi_h, then about y by -theta_h (cos/sin of the angles from h's components).
    has_p = hp > 0.0
    cp = dr.select(has_p, h.x / dr.select(has_p, hp, 1.0), 1.0)
    sp = dr.select(has_p, h.y / dr.select(has_p, hp, 1.0), 0.0)
    x1 = L.x * cp + L.y * sp
    y1 = -L.x * sp + L.y * cp
    ct, st = h.z / hl, hp / hl
    dx = x1 * ct - L.z * st
    dz = x1 * st + L.z * ct
    theta_d = dr.atan2(dr.sqrt(dx * dx + y1 * y1), dz)
    phi_d = dr.atan2(y1, dx)
    phi_d = dr.select(phi_d < 0.0, phi_d + dr.pi, phi_d)
    half_pi = 0.5 * dr.pi
    i_th = dr.select(theta_h <= 0.0, 0, mi.Int32(dr.floor(90.0 * dr.sqrt(theta_h / half_pi))))
    i_td = mi.Int32(dr.floor(theta_d / half_pi * 90.0))
    i_pd = mi.Int32(dr.floor(phi_d / dr.pi * 180.0))
    i_th, i_td, i_pd = (dr.clip(i, 0, n - 1) for i, n in ((i_th, 90), (i_td, 90), (i_pd, 180)))
    return i_pd + 180 * (i_td + 90 * i_th)


class MeasuredBSDF(CookTorranceBSDF):
    """The table's values; sample() and pdf() of the Cook-Torrance fit given in the properties."""

    def __init__(self, props):
        CookTorranceBSDF.__init__(self, props)
        self.filename = str(props["filename"])
        table, self.unmeasured = load_table(self.filename)
        self.table = mi.Float(table)

    def _value(self, V, L, active):
        valid = active & (L.z > 0.0) & (V.z > 0.0)
        i = bin_index(L, V) * 3
        rho = mi.Color3f(*(dr.gather(mi.Float, self.table, i + c, valid) for c in range(3)))
        return dr.select(valid, rho * L.z, 0.0)

    # The table's value, the proposal's density.
    def _eval_pdf(self, V, L, active):
        return self._value(V, L, active), CookTorranceBSDF._eval_pdf(self, V, L, active)[1]

    def to_string(self):
        return f"MeasuredBSDF[{self.filename}, {self.unmeasured} unmeasured bins, proposal p_spec={self.p_spec:.4f}]"


def register():
    mi.register_bsdf("glossy_measured", lambda props: MeasuredBSDF(props))


def bsdf_dict(filename, proposal_fit):
    """Scene-dictionary entry: the table at filename, sampled by a cook-torrance fit {kd, ks, m, eta}."""
    d = {"type": "glossy_measured", "filename": str(filename), "m": float(proposal_fit["m"]),
         "eta": float(proposal_fit["eta"])}
    for name in ("kd", "ks"):
        for channel, value in zip("rgb", proposal_fit[name]):
            d[f"{name}_{channel}"] = float(value)
    return d
