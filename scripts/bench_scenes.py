"""Scene files for `make bench` (docs/bench.md), written as OBJ + MTL.

bunny-glass: glmark2-data's bunny.obj, opaque, inside a transparent sphere (the frame the
golden model and llvmpipe race on). sphere-S: one opaque sphere of S slices and S/2 stacks,
the same size on screen whatever S (the triangle-count sweep).
"""
import math
import os

BUNNY = "/usr/share/glmark2/models/bunny.obj"


def _sphere(radius, slices, stacks):
    """Vertices and faces of a UV sphere, counter-clockwise seen from outside (y up)."""
    verts = []
    for j in range(stacks + 1):
        theta = math.pi * j / stacks
        for i in range(slices):
            phi = 2 * math.pi * i / slices
            verts.append((radius * math.sin(theta) * math.cos(phi), radius * math.cos(theta),
                          radius * math.sin(theta) * math.sin(phi)))

    def at(j, i):
        return j * slices + i % slices

    faces = []
    for j in range(stacks):
        for i in range(slices):
            a, b, c, d = at(j, i), at(j, i + 1), at(j + 1, i + 1), at(j + 1, i)
            if j > 0:
                faces.append((a, b, d))
            if j < stacks - 1:
                faces.append((b, c, d))
    return verts, faces


def _write_atomic(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def _obj_lines(verts, faces, base):
    """OBJ lines for a mesh whose first vertex gets the 1-based index base."""
    out = ["v %.6f %.6f %.6f" % v for v in verts]
    out += ["f %d %d %d" % (a + base, b + base, c + base) for a, b, c in faces]
    return out


def bunny_glass(out_dir):
    """Writes bunny-glass.obj/.mtl into out_dir; returns the .obj path."""
    if not os.path.isfile(BUNNY):
        raise FileNotFoundError(f"{BUNNY} is missing: install glmark2-data (make setup)")
    with open(BUNNY) as f:
        bunny = [line.rstrip("\n") for line in f]
    bunny_vertices = sum(1 for line in bunny if line.startswith("v "))
    verts, faces = _sphere(1.25, 64, 32)
    lines = ["mtllib bunny-glass.mtl", "usemtl bunny"] + bunny + ["usemtl glass"]
    lines += _obj_lines(verts, faces, bunny_vertices + 1)
    _write_atomic(os.path.join(out_dir, "bunny-glass.mtl"),
                  "newmtl bunny\nKd 0.85 0.75 0.6\nd 1\n"
                  "newmtl glass\nKd 0.3 0.6 0.9\nd 0.35\n")
    path = os.path.join(out_dir, "bunny-glass.obj")
    _write_atomic(path, "\n".join(lines) + "\n")
    return path


def sphere(out_dir, slices):
    """Writes sphere-SLICES.obj (opaque, grey) into out_dir; returns its path."""
    verts, faces = _sphere(1.0, slices, max(2, slices // 2))
    path = os.path.join(out_dir, f"sphere-{slices}.obj")
    _write_atomic(path, "\n".join(_obj_lines(verts, faces, 1)) + "\n")
    return path
