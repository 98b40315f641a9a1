"""The highlight section of compare.py: how much light a sharp metal lobe's highlight of a small bright source
carries in glossy, in Mitsuba 3 and in an independent quadrature, on the benchmark's sphere.

Each case is a lat-long map (512 x 256) of a dim uniform background (0.1) with one square source of radiance
2000 (2 x 2 or 1 x 1 texels, at a place whose highlight the camera sees), and a sharp Cook-Torrance E2 fit.
Every renderer's excess image is its render of the map minus its render of the background alone at the same
seed (so the background's own light and noise cancel but for the source's), and the figure is the excess
luminance summed over the highlight's window: the pixels whose reflected ray passes within 8 degrees of the
source, where the quadrature is computed.

The quadrature is NumPy alone: the analytic unit sphere, 4 x 4 image samples per pixel, the source as the
bilinear lookup of the map convention glossy and Mitsuba 3 share (docs/rendering.md: x = u W - 1/2,
y = v (H - 1)) integrated over 24 x 24 points per texel of its footprint, and the fit's BRDF written from
shared/spec/models.md section 3 (not glossy's code, not the Mitsuba plugin). The mesh sphere the renderers
draw differs from it by its facets' normals only, well below a percent of the highlight's light.
"""

import math

import numpy as np

import scene as bench_scene

WIDTH, HEIGHT = 512, 256
BACKGROUND, RADIANCE = 0.1, 2000.0
LUMINANCE = np.array([0.2126, 0.7152, 0.0722])
# (label, material file, fit): the ss440 (m = 0.0136), hematite (m = 0.0165) and the efficiency
# table's steel (m = 0.0125).
MATERIALS = (("ss440 CT E2", "materials/library/merl/ss440.toml", "cook-torrance:E2"),
             ("hematite CT E2", "materials/library/merl/hematite.toml", "cook-torrance:E2"),
             ("steel CT E2", "materials/library/merl/steel.toml", "cook-torrance:E2"))
# (column, row, size): the top-left texel of the source and its side in texels.
PLACES = ((218, 79, 2), (240, 70, 2), (200, 95, 2), (150, 120, 2), (226, 84, 1))


def source_map(column, row, size):
    image = np.full((HEIGHT, WIDTH, 3), BACKGROUND, np.float32)
    image[row:row + size, column:column + size] = RADIANCE
    return image


def _fresnel(c, eta):
    g = np.sqrt(np.maximum(eta * eta - 1.0 + c * c, 0.0))
    a = (g - c) / (g + c)
    b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0)
    return 0.5 * a * a * (1.0 + b * b)


def cook_torrance(fit, n, l, v):
    """rho(L, V) of models.md section 3 for unit vectors [..., 3] (n the normal), RGB in the last axis."""
    h = l + v
    h /= np.linalg.norm(h, axis=-1, keepdims=True)
    nl, nv, nh, vh = ((n * l).sum(-1), (n * v).sum(-1), (n * h).sum(-1), (v * h).sum(-1))
    ok = (nl > 0) & (nv > 0) & (vh > 0)
    nh = np.clip(nh, 1e-9, 1.0)
    m = float(fit["m"])
    d = np.exp(-(1.0 - nh * nh) / (nh * nh) / (m * m)) / (m * m * nh ** 4)
    g = np.minimum(1.0, np.minimum(2 * nh * nv / vh, 2 * nh * nl / vh))
    spec = d * _fresnel(vh, float(fit["eta"])) * g / (math.pi * np.maximum(nl, 1e-12) * np.maximum(nv, 1e-12))
    rho = np.asarray(fit["kd"]) / math.pi + np.asarray(fit["ks"]) * spec[..., None]
    return np.where(ok[..., None], rho, 0.0)


def _source_points(column, row, size, per_texel=24):
    """Directions [k, 3] and weights (radiance excess x solid angle) [k] of the source's bilinear footprint."""
    lo_x, lo_y = column - 1, row - 1
    xs = lo_x + (np.arange((size + 2) * per_texel) + 0.5) / per_texel
    ys = lo_y + (np.arange((size + 2) * per_texel) + 0.5) / per_texel
    x, y = np.meshgrid(xs, ys)

    def texel(cx, ry):
        return ((cx >= column) & (cx < column + size) & (ry >= row) & (ry < row + size)) * (RADIANCE - BACKGROUND)

    x0, y0 = np.floor(x), np.floor(y)
    fx, fy = x - x0, y - y0
    value = ((1 - fx) * (1 - fy) * texel(x0, y0) + fx * (1 - fy) * texel(x0 + 1, y0)
             + (1 - fx) * fy * texel(x0, y0 + 1) + fx * fy * texel(x0 + 1, y0 + 1))
    theta, phi = math.pi * y / (HEIGHT - 1), 2 * math.pi * (x + 0.5) / WIDTH
    dirs = np.stack([np.sin(theta) * np.sin(phi), np.cos(theta), -np.sin(theta) * np.cos(phi)], -1).reshape(-1, 3)
    weight = (value * (2 * math.pi / WIDTH) * (math.pi / (HEIGHT - 1)) * np.sin(theta) / per_texel ** 2).reshape(-1)
    keep = weight > 0
    return dirs[keep], weight[keep]


def quadrature(fit, column, row, size, image_size, samples=4, window_degrees=8.0):
    """The excess image [image_size, image_size, 3] the source adds, within the highlight's window (0 outside),
    and the window's mask."""
    dirs, weight = _source_points(column, row, size)
    centre = (dirs * weight[:, None]).sum(0)
    centre /= np.linalg.norm(centre)
    eye = np.array(bench_scene.EYE)
    forward = np.array(bench_scene.TARGET) - eye
    forward /= np.linalg.norm(forward)
    right = np.cross(forward, np.array(bench_scene.UP))
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    t = math.tan(math.radians(bench_scene.YFOV_DEGREES) / 2)
    image = np.zeros((image_size, image_size, 3))
    window = np.zeros((image_size, image_size), bool)
    offsets = (np.arange(samples) + 0.5) / samples
    for py in range(image_size):
        sx = (np.arange(image_size)[:, None] + offsets[None, :]).reshape(-1)
        sy = py + offsets
        gx, gy = np.meshgrid(sx, sy)  # [samples, image_size * samples]
        x, y = gx / image_size * 2 - 1, 1 - gy / image_size * 2
        d = forward + (x * t)[..., None] * right + (y * t)[..., None] * up
        d /= np.linalg.norm(d, axis=-1, keepdims=True)
        b = (d * eye).sum(-1)
        disc = b * b - (eye @ eye - 1.0)
        hit = disc > 0
        p = eye + (-b - np.sqrt(np.maximum(disc, 0)))[..., None] * d
        v = -d
        mirror = 2 * (p * v).sum(-1, keepdims=True) * p - v
        near = hit & ((mirror * centre).sum(-1) > math.cos(math.radians(window_degrees)))
        window[py] = near.reshape(samples, image_size, samples).any(axis=(0, 2))
        if not near.any():
            continue
        pn, vn = p[near], v[near]
        total = np.zeros((pn.shape[0], 3))
        for k in range(0, len(weight), 4096):
            lk, wk = dirs[k:k + 4096], weight[k:k + 4096]
            rho = cook_torrance(fit, pn[:, None, :], lk[None], vn[:, None, :])
            cos = np.maximum((pn[:, None, :] * lk[None]).sum(-1), 0.0)
            total += (rho * (cos * wk[None, :])[..., None]).sum(1)
        full = np.zeros(gx.shape + (3,))
        full[near] = total
        image[py] = full.reshape(samples, image_size, samples, 3).mean(axis=(0, 2))
    return image, window


def light(excess, window):
    """The highlight's light: excess luminance summed over the window."""
    return float((excess @ LUMINANCE)[window].sum())
