"""The benchmark scene, generated once and written for both renderers.

A UV sphere of radius 1 (128 segments x 64 rings, vertex normals), the same construction as
scenes/make_scenes.cpp (a lathed half circle, the seam's vertices duplicated, the poles' zero-area
triangles left out, every triangle wound to face its vertex normals). It is written

  * as glTF 2.0 (sphere.gltf + sphere.bin) for glossy: the material binds a glossy material through
    extras.glossy, and the camera (at (0, 1, 4) looking at the origin, 35 deg vertical FOV) is a node;
  * as binary PLY (sphere.ply, float positions and normals, the same triangles) for Mitsuba.

Both files hold the very same float32 arrays. Numpy only: this runs inside the Mitsuba venv.
"""

import json
import math
from pathlib import Path

import numpy as np

SEGMENTS, RINGS, RADIUS = 128, 64, 1.0
EYE, TARGET, UP = (0.0, 1.0, 4.0), (0.0, 0.0, 0.0), (0.0, 1.0, 0.0)
YFOV_DEGREES = 35.0


def uv_sphere(radius=RADIUS, segments=SEGMENTS, rings=RINGS):
    """(positions float32 [n,3], normals float32 [n,3], indices uint32 [t,3])."""
    a = -math.pi / 2 + math.pi * np.arange(rings + 1) / rings          # profile angle, pole to pole
    phi = 2.0 * math.pi * np.arange(segments + 1) / segments           # seam duplicated
    around = np.stack([np.cos(phi), np.zeros_like(phi), -np.sin(phi)], axis=1)   # [S+1, 3]
    px, py = radius * np.cos(a), radius * np.sin(a)                    # profile points
    nx, ny = np.cos(a), np.sin(a)                                      # outward profile normals
    pos = around[None, :, :] * px[:, None, None] + np.array([0.0, 1.0, 0.0]) * py[:, None, None]
    nrm = around[None, :, :] * nx[:, None, None] + np.array([0.0, 1.0, 0.0]) * ny[:, None, None]
    nrm /= np.linalg.norm(nrm, axis=2, keepdims=True)
    positions = pos.reshape(-1, 3).astype(np.float32)
    normals = nrm.reshape(-1, 3).astype(np.float32)

    cols = segments + 1
    i, j = np.meshgrid(np.arange(rings), np.arange(segments), indexing="ij")
    a_ = (i * cols + j).ravel()
    b_, c_, d_ = a_ + 1, a_ + cols + 1, a_ + cols
    tris = np.concatenate([np.stack([a_, b_, c_], 1), np.stack([a_, c_, d_], 1)])
    p = positions.astype(np.float64)
    n = np.cross(p[tris[:, 1]] - p[tris[:, 0]], p[tris[:, 2]] - p[tris[:, 0]])
    keep = np.linalg.norm(n, axis=1) >= 1e-12                          # drop the poles' collapsed triangles
    tris, n = tris[keep], n[keep]
    shading = normals[tris].astype(np.float64).sum(axis=1)
    flip = (n * shading).sum(axis=1) < 0.0
    tris[flip] = tris[flip][:, [0, 2, 1]]
    return positions, normals, tris.astype(np.uint32)


def look_at_quaternion(eye, target, up):
    """Rotation (x, y, z, w) of a glTF camera node at eye looking at target (glTF cameras look down -Z)."""
    eye, target, up = map(np.asarray, (eye, target, up))
    z = eye - target
    z = z / np.linalg.norm(z)
    x = np.cross(up, z)
    x = x / np.linalg.norm(x)
    y = np.cross(z, x)
    m = np.stack([x, y, z], axis=1)                                    # columns: camera axes in world
    w = math.sqrt(max(0.0, 1.0 + m[0, 0] + m[1, 1] + m[2, 2])) / 2.0
    if w > 1e-6:
        return [(m[2, 1] - m[1, 2]) / (4 * w), (m[0, 2] - m[2, 0]) / (4 * w), (m[1, 0] - m[0, 1]) / (4 * w), w]
    raise ValueError("camera rotation of 180 degrees is not handled")


def write_gltf(path, positions, normals, indices, material, width, height):
    """material: dict for the glTF material (name, and either extras.glossy or a baseColorFactor)."""
    path = Path(path)
    bin_name = path.with_suffix(".bin").name
    blobs = [positions.tobytes(), normals.tobytes(), indices.tobytes()]
    offsets = np.cumsum([0] + [len(b) for b in blobs])
    gltf = {
        "asset": {"version": "2.0", "generator": "glossy bench/mitsuba/scene.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [
            {"name": "Sphere", "mesh": 0},
            {"name": "Camera", "camera": 0, "translation": list(EYE),
             "rotation": look_at_quaternion(EYE, TARGET, UP)},
        ],
        "cameras": [{"name": "Camera", "type": "perspective",
                     "perspective": {"yfov": math.radians(YFOV_DEGREES), "aspectRatio": width / height,
                                     "znear": 0.05, "zfar": 100.0}}],
        "meshes": [{"name": "Sphere", "primitives": [
            {"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0, "mode": 4}]}],
        "materials": [material],
        "buffers": [{"uri": bin_name, "byteLength": int(offsets[-1])}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": int(offsets[0]), "byteLength": len(blobs[0]), "target": 34962},
            {"buffer": 0, "byteOffset": int(offsets[1]), "byteLength": len(blobs[1]), "target": 34962},
            {"buffer": 0, "byteOffset": int(offsets[2]), "byteLength": len(blobs[2]), "target": 34963},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": len(positions),
             "min": positions.min(axis=0).tolist(), "max": positions.max(axis=0).tolist()},
            {"bufferView": 1, "componentType": 5126, "type": "VEC3", "count": len(normals)},
            {"bufferView": 2, "componentType": 5125, "type": "SCALAR", "count": int(indices.size)},
        ],
    }
    path.with_suffix(".bin").write_bytes(b"".join(blobs))
    path.write_text(json.dumps(gltf, indent=1) + "\n")


def write_ply(path, positions, normals, indices):
    header = (
        "ply\nformat binary_little_endian 1.0\ncomment glossy bench/mitsuba/scene.py\n"
        f"element vertex {len(positions)}\n"
        "property float x\nproperty float y\nproperty float z\n"
        "property float nx\nproperty float ny\nproperty float nz\n"
        f"element face {len(indices)}\nproperty list uchar uint vertex_indices\nend_header\n"
    )
    vertices = np.concatenate([positions, normals], axis=1).astype("<f4")
    faces = np.zeros(len(indices), dtype=[("n", "u1"), ("i", "<u4", (3,))])
    faces["n"] = 3
    faces["i"] = indices
    Path(path).write_bytes(header.encode("ascii") + vertices.tobytes() + faces.tobytes())


def write_sphere_gltf(path, material_file, fit, width, height):
    """One more glTF of the same sphere (own .bin beside it) bound to material_file's fit through extras.glossy."""
    positions, normals, indices = uv_sphere()
    write_gltf(path, positions, normals, indices,
               {"name": "object", "extras": {"glossy": {"material": str(material_file), "fit": fit}}}, width, height)


def write_scene(out_dir, width, height, material_file, fit):
    """Writes sphere.gltf/.bin (bound to material_file's fit), diffuse.gltf/.bin (grey Lambertian, for the
    environment-orientation check) and sphere.ply into out_dir. Returns the triangle count."""
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    positions, normals, indices = uv_sphere()
    write_gltf(out_dir / "sphere.gltf", positions, normals, indices,
               {"name": "object", "extras": {"glossy": {"material": str(material_file), "fit": fit}}}, width, height)
    write_gltf(out_dir / "diffuse.gltf", positions, normals, indices,
               {"name": "grey", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1.0],
                                                          "metallicFactor": 0.0, "roughnessFactor": 1.0}},
               width, height)
    write_ply(out_dir / "sphere.ply", positions, normals, indices)
    return len(indices)
